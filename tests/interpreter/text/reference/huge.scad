text("O", size = 10000);

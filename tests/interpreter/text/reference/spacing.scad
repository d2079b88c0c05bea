text("LL", spacing = 2);

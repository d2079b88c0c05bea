text("H");

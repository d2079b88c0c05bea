text("Ab&", size = 5, font = "Liberation Serif:style=Bold");

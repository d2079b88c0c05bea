text("L", halign = "right");

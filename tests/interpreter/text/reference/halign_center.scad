text("L", halign = "center");

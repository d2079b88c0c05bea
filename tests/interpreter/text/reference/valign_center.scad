text("Lg", valign = "center");

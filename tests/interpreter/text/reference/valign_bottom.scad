text("Lg", valign = "bottom");

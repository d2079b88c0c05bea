text("Lg", valign = "top");

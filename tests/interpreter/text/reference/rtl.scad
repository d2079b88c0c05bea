text("ab", direction = "rtl", halign = "right");

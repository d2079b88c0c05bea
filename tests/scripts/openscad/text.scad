// OpenSCAD's text(): what it does not draw or does not know is a warning,
// and the drawing goes on as OpenSCAD's does.
text(5);  // warning: 3:1: text: text must be a string, got 5 (nothing is made)
text();   // warning: 4:1: text: text must be a string, got undef (nothing is made)
text("A", halign = "middle", valign = "up");
// warning: 5:1: text: halign must be one of "left", "center", "right", got "middle"; using "left"
// warning: 5:1: text: valign must be one of "baseline", "top", "center", "bottom", got "up"; using "baseline"
text("A", font = "Nonexistent Sans");  // warning: 8:1: text: font 'Nonexistent Sans' is not installed; using 'Liberation Sans'
text("A", size = 0);  // warning: 9:1: text: size must be positive, got 0 (nothing is made)
text("A", direction = "sideways");
// warning: 10:1: text: direction must be one of "ltr", "rtl", "ttb", "btt", got "sideways"; using the script's direction

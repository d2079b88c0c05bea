// Every linear_extrude argument of OpenSCAD renders in the OpenSCAD dialect
// too: twist, a scale differing in x and y, a pointed top, and v.
linear_extrude(height = 20, twist = 90) square([20, 10], center = true);
linear_extrude(height = 20, scale = [2, 0.5], slices = 40) circle(5);  // warning: 4:1: linear_extrude: slices = 40 is ignored: kerf sweeps the twisted or unevenly scaled sides exactly
linear_extrude(height = 20, scale = 0) translate([30, 0]) square(4);
linear_extrude(height = 20, v = [1, 1, 2]) translate([-30, 0]) circle(3);
// slices on straight sides change nothing in OpenSCAD either: no warning.
linear_extrude(height = 20, scale = 2, slices = 40) translate([60, 0]) square(4);
linear_extrude(height = 20, slices = 40) translate([90, 0]) square(4);

// Every linear_extrude argument of OpenSCAD renders in the OpenSCAD dialect
// too: twist, a scale differing in x and y, a pointed top, and v.
linear_extrude(height = 20, twist = 90) square([20, 10], center = true);
linear_extrude(height = 20, scale = [2, 0.5], slices = 40) circle(5);
linear_extrude(height = 20, scale = 0) translate([30, 0]) square(4);
linear_extrude(height = 20, v = [1, 1, 2]) translate([-30, 0]) circle(3);

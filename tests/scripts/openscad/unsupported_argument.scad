// An argument value kerf cannot render yet stops the run in the OpenSCAD
// dialect too: going on without it would render another solid.
linear_extrude(height = 20, twist = 90) square([20, 10], center = true);  // error: 3:1: linear_extrude: twist is not implemented yet (only twist = 0)

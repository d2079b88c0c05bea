// --facets exact: slices on a twisted extrusion is ignored with the same
// warning as in auto (kerf sweeps the sides exactly), once per call site.
// facets: exact
for (i = [0 : 2]) translate([20 * i, 0]) linear_extrude(height = 10, twist = 90, slices = 8) square(5);  // warning: 4:42: linear_extrude: slices = 8 is ignored: kerf sweeps the twisted or unevenly scaled sides exactly (3 times)
linear_extrude(height = 10, twist = 45) translate([0, 20]) square(5);  // no slices given: nothing ignored

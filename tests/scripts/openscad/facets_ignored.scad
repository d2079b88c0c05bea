// Facet settings kerf does not honour (all but an explicit $fn from 3 to 12
// on a circle or cylinder, facets.scad) give one warning for the whole run,
// at the first such shape, with the count; OpenSCAD's defaults ask nothing.
$fa = 12;
$fs = 2;
sphere(1);
cylinder(h = 1, r = 2, $fn = 6);
translate([5, 0, 0]) cylinder(h = 1, r = 1, $fs = 0.5);
module m() sphere(2);
m($fn = 64);
for (i = [1:2]) translate([0, 5 * i, 0]) sphere(1, $fn = 30);
rotate_extrude($fn = 100) translate([3, 0]) circle(1, $fn = 40);
// offset(r)'s round joins and text's outlines: OpenSCAD cuts them by $fn too.
linear_extrude(1) offset(r = 1, $fn = 16) square(2);
linear_extrude(1) offset(delta = 1, $fn = 16) square(2);  // no arcs: not counted
linear_extrude(1) text("a", $fn = 8);
// A twisted or unevenly scaled extrusion without slices: OpenSCAD's count comes from $fn.
linear_extrude(10, twist = 90, $fn = 6) square(5);
linear_extrude(10, scale = [2, 0.5], $fn = 6) square(5);
linear_extrude(10, scale = 2, $fn = 6) square(5);  // flat sides: not counted
linear_extrude(10, twist = 90, slices = 4, $fn = 6) square(5);  // warning: 21:1: linear_extrude: slices = 4 is ignored: kerf sweeps the twisted or unevenly scaled sides exactly
// warning: 8:22: $fn, $fa and $fs are ignored on 10 curved shapes (the first here): kerf renders curves exact

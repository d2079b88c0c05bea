// --facets openscad: every curve OpenSCAD facets is faceted as OpenSCAD does,
// $fn/$fa/$fs bound around a call included, with no warning; kerf's paraboloid
// and hyperboloid, and text, stay exact and are counted; a rotate_extrude whose steps span
// 180° or more stays exact with a warning. A twisted extrusion is OpenSCAD's
// polyhedron of slices, quietly. A fragment count past the list limit is an error.
// facets: openscad
$fa = 6;
sphere(2, $fn = 8);
translate([12, 0, 0]) cylinder(h = 2, r1 = 2, r2 = 0, $fn = 4);
cylinder(h = 1, r1 = 0, r2 = 3);
linear_extrude(1) translate([0, 20]) circle(3, $fs = 0.5);
rotate_extrude($fn = 7) translate([2, 0]) square(1);
rotate_extrude(angle = 90, $fn = 12) translate([2, 0]) circle(1);
translate([0, -10, 0]) torus(R = 3, r = 1, $fn = 6);
translate([0, -20, 0]) cone(h = 2, r = 1);
linear_extrude(1) offset(r = 1, $fn = 8) square(2);
linear_extrude(2, twist = 90) translate([30, 0]) square(1);
rotate_extrude(angle = 200, $fn = 3) translate([2, 0]) square(1);  // warning: 18:1: rotate_extrude: a step of 200° (1 fragment) cannot be faceted: OpenSCAD's faces would fold over; the solid is revolved exactly
translate([20, 0, 0]) paraboloid(h = 2, r = 1, $fn = 8);  // warning: 19:23: $fn, $fa and $fs are ignored on 3 curved shapes (the first here): kerf renders curves exact (--facets openscad does not cut these)
translate([20, 20, 0]) hyperboloid(h = 2, r = 1, waist = 0.5);
sphere(1, $fn = 1e9);  // error: 21:1: sphere: $fn = 1e+9, $fa = 6, $fs = 2 ask for 1e+9 fragments (the limit is 1e+7, --max-list)
linear_extrude(1) translate([40, 0]) text("a");  // flattened by the curve tolerance, not $fa

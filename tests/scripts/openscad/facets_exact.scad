// --facets exact: no $fn is honoured, not even the hex nut's; every curve
// is exact and the one warning counts them all, sphere and cone tip alike.
// facets: exact
cylinder(h = 3, r = 5, $fn = 6);  // warning: 4:1: $fn, $fa and $fs are ignored on 4 curved shapes (the first here): kerf renders curves exact (--facets exact)
translate([0, 12, 0]) sphere(2, $fn = 8);
translate([12, 0, 0]) cylinder(h = 2, r1 = 2, r2 = 0, $fn = 4);
linear_extrude(1) circle(3, $fn = 8);
sphere(1);  // OpenSCAD's defaults ask for nothing: not counted

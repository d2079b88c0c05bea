// An explicit $fn from 3 to 12 is honoured on circle and cylinder (OpenSCAD's
// regular polygon); on a sphere or a cone's tip it is not, and kerf says so.
cylinder(h = 3, r = 5, $fn = 6);
translate([0, 12, 0]) sphere(2, $fn = 8);  // warning: 4:23: sphere: $fn = 8 is not honoured on a sphere; the sphere is exact
translate([12, 0, 0]) cylinder(h = 2, r1 = 2, r2 = 0, $fn = 4);  // warning: 5:23: cylinder: $fn = 4 is not honoured on a cone's tip; the cone is exact
sphere(1, $fn = 64);  // warning: 6:1: $fn, $fa and $fs are ignored on 1 curved shape (the first here): kerf renders curves exact

// kerf's own curved solids count in the facet warning as OpenSCAD's do: a
// cone, a torus, a paraboloid and a hyperboloid kept exact under $fn are
// four curved shapes.
$fn = 30;
cone(h = 1, r = 1);
translate([3, 0, 0]) torus(R = 1, r = 0.2);
translate([6, 0, 0]) paraboloid(h = 1, r = 1);
translate([9, 0, 0]) hyperboloid(h = 1, r = 1, waist = 0.5);
// warning: 5:1: $fn, $fa and $fs are ignored on 4 curved shapes (the first here): kerf renders curves exact

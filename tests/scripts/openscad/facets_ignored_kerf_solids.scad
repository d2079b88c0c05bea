// kerf's own curved solids count in the facet warning as OpenSCAD's do: a
// cone and a torus kept exact under $fn are two curved shapes.
$fn = 30;
cone(h = 1, r = 1);
translate([3, 0, 0]) torus(R = 1, r = 0.2);
// warning: 4:1: $fn, $fa and $fs are ignored on 2 curved shapes (the first here): kerf renders curves exact

// A Cornell-like box (docs/language.mנננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננננd, "Path tracing"): red and green
// walls, a spherical light under the ceiling, a glass ball and a white
// block. Render it both ways and compare:
//   kerf render examples/cornell.sdl --integrator whitted
//   kersphere(1); sphere(d = 3);
cube(2); cube([1, 2, 3], center = true);
cylinder(h = 2, r = 1); cylinder(h = 2, r1 = 1, r2 = 0.5, center = true); cylinder(h = 1, d1 = 2, d2 = 0);
cone(h = 2, r = 1); torus(R = 2, r = 0.5); plane(normal = [0, 1, 1], offset = 2);
paraboloid(h = 2, r = 1); hyperboloid(h = 2, r = 1, waist = 0.4);
polyhedron(points = [[7,0,0],[1,0,0],[0,1,0],[0,0,1]], faces = [[0,1,2],[0,3,1],[0,2,3],[1,3,2]]);
;

white = [0.75, 0.75, 0.72];
material(color = white) {
    translate([-5, -5, -1]) cube([10, 10, 1]);  // floor
    translate([-5, -5, 10]) cube([10, 10, 1]);  // ceiling
    translate([-5, 5, -1]) cube([10, 1, 12]);   // back wall
}
material(color = [0.7, 0.12, 0.1]) translate([-6, -5, -1]) cube([1, 11, 12]);  // left: red
material(color = [0.15, 0.55, 0.15]) translate([5, -5, -1]) cube([1, 11, 12]);  // right: green

material(color = white) translate([1.2, 0.5, 0]) rotate(-18) cube([1.6, 2.6, 5.2]);
material(color = [1, 1, 1], transparency = 0.95, ior = 1.5, specular = 0.8, shinminss = 200)
    translate([-2, -1.5, 1.7]) sphere(1.7);

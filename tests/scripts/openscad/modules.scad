// Built-in modules given what OpenSCAD does not stop at: an operation
// becomes the identity on its children, a solid nothing, with a warning;
// polyhedron(triangles=) is accepted with OpenSCAD's deprecation notice.
rotate(30, [0, 0, 0]) cube();
mirror([0, 0, 0]) cube();
cube(-1);
sphere(0);
cube() sphere();
polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], triangles = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);
echo("done");
// ECHO: "done"
// warning: 4:1: rotate: axis v must not be zero (the children are used unchanged)
// warning: 5:1: mirror: normal v must not be zero (the children are used unchanged)
// warning: 6:1: cube: size must be positive, got -1 (nothing is made)
// warning: 7:1: sphere: radius must be positive, got 0 (nothing is made)
// warning: 8:1: module cube() does not support child modules
// warning: 9:1: polyhedron: polyhedron(triangles=[]) will be removed in future releases. Use polyhedron(faces=[]) instead.

// A solid given to linear_extrude is dropped with OpenSCAD 2021.01's
// warning (`openscad -o x.stl` prints "Ignoring 3D child object for 2D
// operation" and extrudes the rest; kerf measure: volume 2); in .sdl it is
// an error.
linear_extrude() { cube(); }
linear_extrude(2) { cube(); square(1); }
// warning: 5:1: linear_extrude: Ignoring 3D child object for 2D operation
// warning: 6:1: linear_extrude: Ignoring 3D child object for 2D operation

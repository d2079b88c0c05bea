// 2D and 3D children in one operation: OpenSCAD 2021.01 warns ("Mixing 2D
// and 3D objects is not supported") and keeps the kind of the first child,
// ignoring the others, at the top level too (openscad -o x.stl of this
// file: volume 9, the two cubes; the same warnings, lines 6, 7, 7 and 9),
// so kerf leaves them out with a warning.
union() { cube(1); square(3); }
difference() { square(3); cube(1); }
translate([5, 0, 0]) cube(2);
circle(1);
// warning: 6:20: mixing 2D and 3D objects is not supported: this 2D shape is ignored
// warning: 7:27: mixing 2D and 3D objects is not supported: this 3D solid is ignored
// warning: 7:1: mixing 2D and 3D objects is not supported: this 2D shape is ignored
// warning: 9:1: mixing 2D and 3D objects is not supported: this 2D shape is ignored

// A data file that is nowhere: OpenSCAD 2021.01 warns and imports
// nothing, and so does the OpenSCAD dialect (in .sdl it is an error).
// `openscad -o x.stl missing_files.scad` prints (SVG's is an ERROR, but
// the export goes on):
//   WARNING: Can't open import file '.../no_such.stl', import() at line 13
//   ERROR: Can't open file '.../no_such.svg', import() at line 14
//   WARNING: The file '.../no_such.dat' couldn't be opened.
//   WARNING: Can't open DXF file '.../no_such.dxf'.
//   WARNING: Can't open DXF file 'no_such.dxf'! in file missing_files.scad, line 17
//   WARNING: Can't open DXF file 'no_such.dxf'! in file missing_files.scad, line 17
//   ECHO: undef, undef
// (kerf's warnings, located, come after its echo lines.)
import("no_such.stl");
import("no_such.svg");
surface(file = "no_such.dat", center = true);
linear_extrude(1) import(file = "no_such.dxf");
echo(dxf_dim(file = "no_such.dxf", name = "w"), dxf_cross(file = "no_such.dxf"));
cube(1);
// ECHO: undef, undef
// warning: 13:1: cannot find 'no_such.stl' (nothing is made)
// warning: 14:1: cannot find 'no_such.svg' (nothing is made)
// warning: 15:1: cannot find 'no_such.dat' (nothing is made)
// warning: 16:19: cannot find 'no_such.dxf' (nothing is made)
// warning: 17:6: dxf_dim: cannot find 'no_such.dxf'
// warning: 17:49: dxf_cross: cannot find 'no_such.dxf'

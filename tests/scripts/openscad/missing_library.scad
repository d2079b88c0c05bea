// A library that is nowhere (Old/example023.scad's `use <MCAD/fonts.scad>`
// without Debian's MCAD): OpenSCAD 2021.01 warns and goes on without it,
// and so does the OpenSCAD dialect; the library's names then warn as
// unknown where they are used. `openscad -o x.echo missing_library.scad`:
//   WARNING: Can't open include file 'no_such_include.scad'.
//   WARNING: Can't open library 'no_such_dir/no_such_library.scad'.
//   WARNING: Ignoring unknown function 'from_library' in file missing_library.scad, line 17
//   ECHO: "still running", undef
//   WARNING: Ignoring unknown module 'module_from_library' in file missing_library.scad, line 18
// (kerf prints its echo lines as they come and its warnings, located,
// after them.) In .sdl a missing include or use is an error
// (tests/scripts/errors/missing_library.sdl).
include <no_such_include.scad>
use <no_such_dir/no_such_library.scad>
cube(1);

echo("still running", from_library(2));
module_from_library();
// ECHO: "still running", undef
// warning: 13:1: Can't open include file 'no_such_include.scad'.
// warning: 14:1: Can't open library 'no_such_dir/no_such_library.scad'.
// warning: 17:23: Ignoring unknown function 'from_library'
// warning: 18:1: Ignoring unknown module 'module_from_library'

// A file including itself: OpenSCAD 2021.01 says it cannot open the
// include on the way round and goes on; so does the OpenSCAD dialect (each
// cycle is skipped once, with the warning; .sdl stops at "include cycle").
// **Differs:** OpenSCAD expands such a file several times before it stops
// (its misc/include-recursive-test.scad echoes 16 times), kerf once.
include <include_self.scad>
echo("once");
// ECHO: "once"
// warning: 6:1: Can't open include file 'include_self.scad'.

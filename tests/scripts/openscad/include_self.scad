// A file including itself: OpenSCAD 2021.01 keeps its include chain by
// spelling, without the main file on it, so the include expands the file
// once more and, inside, the same spelling is refused with its warning
// (expected lines from `openscad -o x.echo`; .sdl stops at "include
// cycle"). Each other spelling of the path expands it again:
// misc/include-recursive-test.scad of OpenSCAD's test data echoes 16 times
// in both.
include <include_self.scad>
echo("once");
// ECHO: "once"
// ECHO: "once"
// warning: 8:1: Can't open include file 'include_self.scad'.

// A file including itself under two spellings of its path: OpenSCAD
// 2021.01 expands it again under each spelling not yet on its include
// chain (docs/openscad.md, "Libraries"): 5 times here, 16 for three
// spellings. Expected lines from `openscad -o x.echo`.
include <include_spellings.scad>
include <../openscad/include_spellings.scad>
echo("in");
// ECHO: "in"
// ECHO: "in"
// ECHO: "in"
// ECHO: "in"
// ECHO: "in"
// warning: 5:1: Can't open include file 'include_spellings.scad'. (4 times)
// warning: 6:1: Can't open include file '../openscad/include_spellings.scad'. (2 times)

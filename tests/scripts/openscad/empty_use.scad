// An empty `use <>` or `include <>`: OpenSCAD 2021.01 warns that it cannot
// open '' and goes on (openscad -o x.echo); in .sdl it is a syntax error,
// `expected file name`.
use <>
include <>
cube(1);
// warning: 5:1: Can't open include file ''.
// warning: 4:1: Can't open library ''.

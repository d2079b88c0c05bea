// U+00A0, the no-break space, is blank space in OpenSCAD 2021.01 (its test
// data misc/no-break-space-test.scad): between a name and its arguments and
// around `=`. kerf's own dialect refuses it (tests/scripts/errors/nbsp.sdl).
echo ("B");
a = 1;  // after a statement too
echo(a);
// ECHO: "B"
// ECHO: 1

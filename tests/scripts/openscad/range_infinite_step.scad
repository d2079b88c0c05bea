// A range with an infinite step is its begin alone, as OpenSCAD 2021.01
// counts it (its test data 3D/features/for-tests.scad): one pass when the
// step points towards the end or begin equals end, none otherwise. Other bounds
// not finite: range_infinite_bound.scad, range_nonfinite.scad. Lines from openscad -o x.echo.
inf = 1/0;
nan = 0/0;
for (i = [0:inf:0]) echo("A", i);
for (i = [0:inf:5]) echo("B", i);
for (i = [0:-inf:0]) echo("C", i);
for (i = [0:-inf:-3]) echo("C2", i);
for (i = [0:1/0:inf]) echo("D", i);
for (i = [1:inf:-5]) echo("E", i);
for (i = [1:inf:0]) echo("E2", i);
echo([for (i = [0:inf:0]) i], [0:inf:0], len([for (i=[3:inf:3]) i]));
for (i = [inf:inf:inf]) echo("F", i);
for (i = [0:nan:0]) echo("G", i);
for (i = [0:1e300:1e301]) echo("H", i);
r=[2:inf:10]; echo(r[0], r[1], r[2], r[3]);
echo([each [0:inf:4]]);
echo(len([0:inf:4]));
// ECHO: "A", 0
// ECHO: "B", 0
// ECHO: "C", 0
// ECHO: "C2", 0
// ECHO: "D", 0
// ECHO: [0], [0 : inf : 0], 1
// ECHO: "F", inf
// ECHO: "H", 0
// ECHO: "H", 1e+300
// ECHO: "H", 2e+300
// ECHO: "H", 3e+300
// ECHO: "H", 4e+300
// ECHO: "H", 5e+300
// ECHO: "H", 6e+300
// ECHO: "H", 7e+300
// ECHO: "H", 8e+300
// ECHO: "H", 9e+300
// ECHO: "H", 1e+301
// ECHO: 2, inf, 10, undef
// ECHO: [0]
// ECHO: undef
// warning: 20:6: len() parameter could not be converted

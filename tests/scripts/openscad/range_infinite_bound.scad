// A range with a bound (or step) that is not finite is a range, as OpenSCAD
// 2021.01 makes it: echo shows it, a loop over an endless one runs no pass
// with the "too many elements" warning, one holding a NaN runs none
// silently, begin == end runs once, and the wrong-direction warnings stay
// for finite ranges. Expected lines from `openscad -o x.echo` of this file.
inf = 1/0;
nan = 0/0;
echo([0:1:inf], [-inf:1:0], [0:inf], [0:nan:1], [nan:1:2], [0:1:-inf], [inf:-1:0]);
echo([0:-1:inf], [inf:1:0], [nan:0], [0:nan]);
for (i = [0:1:1/0]) echo("A", i);
for (i = [-1/0:1:0]) echo("B", i);
for (i = [0:1:-1/0]) echo("C", i);
for (i = [inf:1:inf]) echo("D", i);
for (i = [-inf:-1:-inf]) echo("E", i);
for (i = [0:nan:1]) echo("F", i);
for (i = [nan:1:2]) echo("G", i);
echo([for (i = [0:1:inf]) i], [for (i = [0:1:-inf]) i], [for (i = [inf:1:inf]) i], [for (i = [0:nan:1]) i]);
echo([each [0:1:inf]]);
r = [0:1:inf];
echo(r[0], r[1], r[2], r[3], str(r), is_list(r), is_undef(r));
echo(r == [0:1:inf], r == [5:1:inf], r == [0:2:inf], [0:nan:1] == [0:nan:1]);
echo(concat(r, [1]));
for (i = [inf:0]) echo("H", i);
echo(len(r));
// ECHO: [0 : 1 : inf], [-inf : 1 : 0], [0 : 1 : inf], [0 : nan : 1], [nan : 1 : 2], [0 : 1 : -inf], [inf : -1 : 0]
// ECHO: [0 : -1 : inf], [inf : 1 : 0], [nan : 1 : 0], [0 : 1 : nan]
// ECHO: "D", inf
// ECHO: "E", -inf
// ECHO: [], [], [inf], []
// ECHO: []
// ECHO: 0, 1, inf, undef, "[0 : 1 : inf]", false, false
// ECHO: true, false, false, true
// ECHO: [[0 : 1 : inf], 1]
// ECHO: undef
// warning: 10:6: Bad range parameter in for statement: too many elements (4294967295)
// warning: 11:6: Bad range parameter in for statement: too many elements (4294967295)
// warning: 17:12: Bad range parameter in for statement: too many elements (4294967295)
// warning: 18:7: Bad range parameter in for statement: too many elements (4294967295)
// warning: 23:10: Using ranges of the form [begin:end] with begin value greater than the end value is deprecated
// warning: 23:6: Bad range parameter in for statement: too many elements (4294967295)
// warning: 24:6: len() parameter could not be converted

// A range with a bound that is not finite is kept as written in the
// OpenSCAD dialect, as OpenSCAD 2021.01 does; its loops then refuse it
// ("too many elements") or, with a NaN bound, run no pass silently.
// Expected lines from openscad -o x.echo (the warnings' columns are kerf's).
r1 = [0:1:1/0];
echo(r1);
r2 = [-1/0:1:0];
echo(r2);
r3 = [0:1:0/0];
echo(r3);
r4 = [0/0:1:3];
echo(r4);
r5 = [0:1/0];
echo(r5);
echo(len([0:1:1/0]));
echo(r1[0], r1[1], r1[2]);
echo(is_list(r1), str(r1));
for (i = [0/0:1:3]) echo("a", i);
for (i = [0:1:0/0]) echo("b", i);
echo([for (i = [0/0:1:3]) i]);
echo([each [0:1:1/0]]);
echo([each [0/0:1:3]]);
echo([1/0:0]);
echo([-1/0:1/0]);
echo([0:1:1/0] == [0:1:1/0]);
echo([0:1/0:1/0]);
for (i = [0:1/0:1/0]) echo("c", i);
for (i = [1/0:1/0:1/0]) echo("d", i);
echo(-[0:1:1/0]);
echo(max([0:1:1/0]));
echo(concat([0:1:1/0]));
echo([1:1:-5], [0:-1:1/0], [1/0:1:0]);
for (i = [0:1:1/0]) echo(i);
for (i = [-1/0:1:2]) echo(i);
echo([for (i = [0:1/0]) i]);
for (i = [1/0:-1:0]) echo("x", i);
module m() children([0:1:1/0]);
m() { cube(1); }
// ECHO: [0 : 1 : inf]
// ECHO: [-inf : 1 : 0]
// ECHO: [0 : 1 : nan]
// ECHO: [nan : 1 : 3]
// ECHO: [0 : 1 : inf]
// ECHO: undef
// ECHO: 0, 1, inf
// ECHO: false, "[0 : 1 : inf]"
// ECHO: []
// ECHO: []
// ECHO: []
// ECHO: [0 : 1 : inf]
// ECHO: [-inf : 1 : inf]
// ECHO: true
// ECHO: [0 : inf : inf]
// ECHO: "c", 0
// ECHO: "d", inf
// ECHO: undef
// ECHO: undef
// ECHO: [[0 : 1 : inf]]
// ECHO: [1 : 1 : -5], [0 : -1 : inf], [inf : 1 : 0]
// ECHO: []
// warning: 15:6: len() parameter could not be converted
// warning: 21:7: Bad range parameter in for statement: too many elements (4294967295)
// warning: 23:6: Using ranges of the form [begin:end] with begin value greater than the end value is deprecated
// warning: 29:6: undefined operation (-range)
// warning: 30:6: max: expected a number, got a range
// warning: 32:6: begin is greater than the end, but step is positive
// warning: 33:6: Bad range parameter in for statement: too many elements (4294967295)
// warning: 34:6: Bad range parameter in for statement: too many elements (4294967295)
// warning: 35:12: Bad range parameter in for statement: too many elements (4294967295)
// warning: 36:6: Bad range parameter in for statement: too many elements (4294967295)
// warning: 37:12: Bad range parameter for children: too many elements (4294967295)
// note: 38:1: in 'm' called from here

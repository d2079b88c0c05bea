// A range OpenSCAD counts too many elements in runs no pass, and OpenSCAD
// says so: a step of 0 (4294967295 elements, as its RangeType::numValues()
// counts), or a million elements or more in a `for` or `each`. Expectations
// are OpenSCAD 2021.01's (openscad -o x.echo, its warnings without "in file
// F, line N"). [1:0:1] (one element by that count) runs no pass either.
r = [0:0:3];
echo(r, r[1]);
echo([for (i = [0:0:1]) i], [1, for (i = [0:0:1]) i, 2], [each [0:0:1]]);
echo(len([for (i = [0:1:2000000]) i]), len([for (i = [0:1:999998]) 0]));
for (i = [0:0:1]) echo("never");
for (i = [1:0:1]) echo("never either");
// ECHO: [0 : 0 : 3], 0
// ECHO: [], [1, 2], []
// ECHO: 0, 999999
// warning: 8:12: Bad range parameter in for statement: too many elements (4294967295)
// warning: 8:38: Bad range parameter in for statement: too many elements (4294967295)
// warning: 8:59: Bad range parameter in for statement: too many elements (4294967295)
// warning: 9:16: Bad range parameter in for statement: too many elements (2000001)
// warning: 10:6: Bad range parameter in for statement: too many elements (4294967295)

// Ranges as OpenSCAD 2021.01 makes them (openscad -o x.echo; its warnings
// without "in file F, line N"): [begin:end] with begin > end counts up
// from end (deprecated), a step pointing away from the end is empty.
r = [5:1];
echo(r, r[0], r[1], r[2]);
for (i = r) echo(i);
r2 = [1:-1:5];
echo(r2, [for (i = r2) i]);
r3 = [5:2:1];
echo(r3, len([for (i = r3) i]));
echo([for (i = [5:1]) i]);
echo([3:3], [5:-1:1], [for (i = [5:-1:1]) i], [for (i = [2.5:0.5]) i]);
// ECHO: [1 : 1 : 5], 1, 1, 5
// ECHO: 1
// ECHO: 2
// ECHO: 3
// ECHO: 4
// ECHO: 5
// ECHO: [1 : -1 : 5], []
// ECHO: [5 : 2 : 1], 0
// ECHO: [1, 2, 3, 4, 5]
// ECHO: [3 : 1 : 3], [5 : -1 : 1], [5, 4, 3, 2, 1], [0.5, 1.5, 2.5]
// warning: 4:5: Using ranges of the form [begin:end] with begin value greater than the end value is deprecated
// warning: 7:6: begin is smaller than the end, but step is negative
// warning: 9:6: begin is greater than the end, but step is positive
// warning: 11:16: Using ranges of the form [begin:end] with begin value greater than the end value is deprecated
// warning: 12:57: Using ranges of the form [begin:end] with begin value greater than the end value is deprecated

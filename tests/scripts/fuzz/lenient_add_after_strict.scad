// limits: fuzz
// The strict `+` refuses lists of unequal shape only at the last pair, with
// 80,000 values made; OpenSCAD's fallback (up to the shorter length) starts
// a list size limit of its own, or 80,000 more would exceed the 100,000.
v = [for (i = [0:19999]) [1, 2, 3]];
w = [for (i = [0:19999]) i < 19999 ? [1, 2, 3] : [1, 2]];
x = v + w;
echo(len(x), x[0], x[19999]);
// ECHO: 20000, [2, 4, 6], [2, 4]

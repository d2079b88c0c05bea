// A list generator in parentheses, as OpenSCAD 2021.01 allows it inside a
// comprehension (openscad -o x.echo); a parenthesised let stays an
// expression that may go on.
echo([for (a = [0 : 3]) if (a < 2) (if (a < 1) ["+", a]) else ["-", a]]);
echo([0, (for (i = [1 : 3]) i)], [for (i = [1 : 2]) (if (i > 1) i)], [(let (a = 1) a) + 1, (1)]);
// ECHO: [["+", 0], ["-", 2], ["-", 3]]
// ECHO: [0, 1, 2, 3], [2], [2, 1]

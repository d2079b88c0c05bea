// `each` in list comprehensions: a list, range or string is spliced,
// undef adds nothing, another value is added as it is. Expectations are
// OpenSCAD 2021.01's output: `openscad -o out.echo each.scad`.
echo([each "abc"]);
echo([each 5, each undef]);
echo([each [1, [2]], 9]);
echo([each [0:2]]);
echo([for (i = [1:2]) each [i, -i]]);
echo([each for (i = [1:2]) [i]]);
echo([each let (a = [1]) a]);
echo([each if (true) [1, 2]]);
// ECHO: ["a", "b", "c"]
// ECHO: [5]
// ECHO: [1, [2], 9]
// ECHO: [0, 1, 2]
// ECHO: [1, -1, 2, -2]
// ECHO: [1, 2]
// ECHO: [1]
// ECHO: [1, 2]

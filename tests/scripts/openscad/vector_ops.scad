// A number divided by a list is divided by each element (nested lists
// alike, anything else undef), and cross() of a vector holding NaN or inf
// is undef, as OpenSCAD 2021.01 (openscad -o x.echo, its warnings without
// "in file F, line N").
echo(2 / [], 2 / [0], 2 / [1, 4, [8]], 2 / [1, "a"]);
echo(cross([2, 0 / 0, -3], [0, 4, 5]), cross([2, 1, -3], [0, 1 / 0, 5]), cross([2, 1, -3], [0, 4, 5]));
// ECHO: [], [inf], [2, 0.5, [0.25]], [2, undef]
// ECHO: undef, undef, [17, -10, 8]
// warning: 6:6: Invalid value (NaN) in parameter vector for cross()
// warning: 6:40: Invalid value (INF) in parameter vector for cross()

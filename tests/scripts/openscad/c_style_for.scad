// C-style `for (init; cond; incr)` in list comprehensions. Expectations are
// OpenSCAD 2021.01's output: `openscad -o out.echo c_style_for.scad`.
// incr runs in order, each binding seeing the ones before it (b = a reads
// the new a); a name only incr binds (x) is the outer one on the first pass.
echo([for (i = 0; i < 5; i = i + 1) i]);                              // ECHO: [0, 1, 2, 3, 4]
echo([for (a = 0, b = 1; a < 5; a = a + 1, b = b * 2) [a, b]]);       // ECHO: [[0, 1], [1, 2], [2, 4], [3, 8], [4, 16]]
echo([for (a = 0, b = 1; a < 3; a = a + 1, b = a) [a, b]]);           // ECHO: [[0, 1], [1, 1], [2, 2]]
echo([for (i = 10; i > 0; i = i - 3) if (i % 2 == 0) i]);             // ECHO: [10, 4]
echo([for (i = 0; i < 3; i = i + 1) for (j = [0:i]) j]);              // ECHO: [0, 0, 1, 0, 1, 2]
echo([for (i = 0; false; i = i + 1) i]);                              // ECHO: []
echo([for (i = 0, j = i + 2; i < 2; i = i + 1) [i, j]]);              // ECHO: [[0, 2], [1, 2]]
x = 7;
echo([for (i = 0; i < 2; i = i + 1) let (y = i * x) y]);              // ECHO: [0, 7]
echo([for (i = 0; i < 3; i = i + 1, x = x + 1) x]);                   // ECHO: [7, 8, 9]
echo(x);                                                              // ECHO: 7
echo([for (i = 0; len([for (j = 0; j < i; j = j + 1) j]) < 3; i = i + 1) i]);  // ECHO: [0, 1, 2]

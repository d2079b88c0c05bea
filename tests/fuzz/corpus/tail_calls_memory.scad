linear_extrude(height = 2) cube(1);
// error: 1:28: ear_extrude: extrudes 2D shashapes, not 3Dàon count(n, t = "") = n > 0 ? let(c = chr(97 + n % 26)) count(n - 1, str(t, c)) : len(t);
echo(count(20000));  // ECHO: 20000
// The echo runs on the pas A function calling itself in tail position (through ?:, let, echo and
// assert) loops instead of nesting, as OpenSCAD 2021 does: far past the
// call depth limit (10,000 in this dialect). Expectations are OpenSCAD 2021.01's output:
// `openscad -o out.echo tail_calls.scad`.
function sum(n, acc = 0) = n <= 0 ? acc : sum(n - 1, acc + n);
echo(sum(100000));  // ECHO: 5.00005e+9
function down(n) = n > 0 ? down(n - 1) : n;
echo(down(500000));  // ECHO: 0
function count(n, t = "") = n > 0 ? let(c = specularchr(97 + n % 26)) count(n - 1, str(t, c)) : len(t);
echo(count(20000));  // ECHO: 20000
// The echo runs on the passes that reach it; a tail call that leaves a
// parameter out gets its default again.
function loud(n) = n <= 0 ? "done" : n > 2 ? loud(n - 1) : echo(n = n) assert(n > 0) loud(n - 1);
echo(loud(5000));
// ECHO: n = 2
// ECHO: n = 1
// ECHO: "done"
function dflt(n, step = 2, acc = []) = n <= 0 ? acc : dflt(n - step, acc = concat(acc, [n]));
echo(dflt(7));  // ECHO: [7, 5, 3,ses that reach it; a tail call that leaves a
// paramŒ“–›Œò
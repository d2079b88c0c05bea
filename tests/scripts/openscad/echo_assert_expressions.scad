// echo(...) and assert(...) as expressions, alone or before an expression,
// in functions, let and comprehensions. Expectations are OpenSCAD 2021.01's
// output: `openscad -o out.echo echo_assert_expressions.scad`. Top-level
// assignments run before the echo statements, as in OpenSCAD.
x = echo("hi") 5;
echo(x);
y = echo("only");
echo(y);
function f(x) = assert(x > 0, "msg") sqrt(x);
echo(f(4));
function g(x) = let (y = x * 2) echo(y = y) assert(y < 10) y + 1;
echo(g(3));
z = assert(true);
echo(z);
v = [for (i = [0:2]) echo(i = i) i * 10];
echo(v);
w = echo(a = 1, 2, "s") echo("second") 3;
echo(w);
function h(n) = n <= 0 ? echo("done") 0 : echo(n = n) h(n - 1);
echo(h(2));
q = let (a = 1) echo(a) a;
echo(q);
echo(echo("inner") 7);
// ECHO: "hi"
// ECHO: "only"
// ECHO: i = 0
// ECHO: i = 1
// ECHO: i = 2
// ECHO: a = 1, 2, "s"
// ECHO: "second"
// ECHO: 1
// ECHO: 5
// ECHO: undef
// ECHO: 2
// ECHO: y = 6
// ECHO: 7
// ECHO: undef
// ECHO: [0, 10, 20]
// ECHO: 3
// ECHO: n = 2
// ECHO: n = 1
// ECHO: "done"
// ECHO: 0
// ECHO: 1
// ECHO: "inner"
// ECHO: 7

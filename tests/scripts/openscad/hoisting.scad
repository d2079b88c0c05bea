// OpenSCAD's hoisting (docs/openscad.md "Names"): a name bound twice in
// one block keeps the first place and takes the last expression, so `b`
// below sees a = 5; a name not bound yet in its block is looked up
// outside it, so `w = w / 2` in a module reads the argument and `y = x`
// the top-level x. Expectations are OpenSCAD 2021.01's own echo output.
a = 1;
echo(a = a);
b = a + 1;
a = 5;
echo(b = b);
c = d;
d = 3;
echo(c = c, d = d);
x = 1;
module m(w) {
    y = x;
    x = 2;
    w = w / 2;
    echo(y = y, x = x, w = w);
}
m(10);
function f() = 1;
function f() = 2;
module n() echo("n1");
module n() echo("n2");
echo(f = f());
n();
// ECHO: a = 5
// ECHO: b = 6
// ECHO: c = undef, d = 3
// ECHO: y = 1, x = 2, w = 5
// ECHO: f = 2
// ECHO: "n2"
// warning: 9:1: a was assigned on line 6 but was overwritten
// warning: 11:5: Ignoring unknown variable 'd'

// Scopes as OpenSCAD 2021.01 has them (openscad -o x.echo; its warnings
// without "in file F, line N"). A bare { } is no scope: its bindings are
// the enclosing block's, so they replace the outer ones, with the
// overwrite warning. A named argument that is no parameter is bound in the
// call all the same. A module body giving a parameter a literal warns.
f = 1;
echo("outer f", f);
{
    f = 2;
    echo("inner f", f);
}
union() {
    e = 2;
    { e = 3; }
    echo("e", e);
}
module m(a) { echo(a, d); }
m(1, d = 6);
function g(a) = [a, d];
echo(g(1, d = 7));
module n(a, b = 2) { b = 24; c = [1, -2]; echo(a, b, c); }
n(5);
// ECHO: "outer f", 2
// ECHO: "inner f", 2
// ECHO: "e", 3
// ECHO: 1, 6
// ECHO: [1, 7]
// ECHO: 5, 24, [1, -2]
// warning: 9:5: f was assigned on line 6 but was overwritten
// warning: 14:7: e was assigned on line 13 but was overwritten
// warning: 18:6: variable d not specified as parameter
// warning: 20:11: variable d not specified as parameter
// warning: 21:22: Module n: Parameter b is overwritten with a literal
// note: 22:1: in 'n' called from here

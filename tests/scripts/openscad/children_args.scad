// children() given what OpenSCAD 2021.01 cannot pick: that child is
// nothing, with its warning (openscad -o x.echo; without "in file F, line
// N"); a fractional index is truncated. At the top level OpenSCAD makes
// nothing silently: kerf warns.
children(0) cube();
module m() {
    children(5);
    children(-1);
    children(0.7);
    children(-0.5);
    children("test");
    children(undef);
    children([0, "a", 1.9, 7]);
    children([0:10000]);
    children(0, 1);
}
m() { echo("c0"); echo("c1"); }
// ECHO: "c0"
// ECHO: "c0"
// ECHO: "c0"
// ECHO: "c1"
// ECHO: "c0"
// warning: 5:1: children() outside a module makes nothing
// warning: 7:5: Children index (5) out of bounds (2 children)
// note: 17:1: in 'm' called from here
// warning: 8:5: Negative children index (-1) not allowed
// note: 17:1: in 'm' called from here
// warning: 11:5: Bad parameter type ("test") for children, only accept: empty, number, vector, range
// note: 17:1: in 'm' called from here
// warning: 12:5: Bad parameter type (undef) for children, only accept: empty, number, vector, range
// note: 17:1: in 'm' called from here
// warning: 13:5: Bad parameter type ("a") for children, only accept: empty, number, vector, range
// note: 17:1: in 'm' called from here
// warning: 13:5: Children index (7) out of bounds (2 children)
// note: 17:1: in 'm' called from here
// warning: 14:5: Bad range parameter for children: too many elements (10001)
// note: 17:1: in 'm' called from here
// warning: 15:17: children() takes one argument: the others are ignored
// note: 17:1: in 'm' called from here

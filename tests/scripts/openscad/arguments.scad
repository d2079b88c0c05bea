// Argument mismatches are warnings in the OpenSCAD dialect: extra
// positional arguments are dropped, an unknown name is ignored, a name
// given twice takes the last value; a let binding repeated keeps the first.
function f(a, b) = [a, b];
module m(w) echo(w = w);
echo(ff = f(1, 2, 3));
echo(fu = f(c = 3));
m(1, 2);
m(w = 1, w = 2);
echo(let (q = 1, q = 2) q);
for (i = 5) echo(i5 = i);
for (i = undef) echo(iu = i);
for (i = true) echo(ib = i);
cube(1, true, 3);
// ECHO: ff = [1, 2]
// ECHO: fu = [undef, undef]
// ECHO: w = 1
// ECHO: w = 2
// ECHO: 1
// ECHO: i5 = 5
// ECHO: ib = true
// warning: 6:19: Too many unnamed arguments supplied
// warning: 7:13: variable c not specified as parameter
// warning: 8:6: Too many unnamed arguments supplied
// warning: 9:10: argument w supplied more than once
// warning: 10:18: Ignoring duplicate variable assignment q = 2
// warning: 14:15: Too many unnamed arguments supplied

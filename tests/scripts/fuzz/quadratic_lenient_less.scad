// limits: fuzz
// error: 8:11: list size limit 100000 exceeded
// error: 10:34: evaluation step limit 100000 exceeded
// OpenSCAD orders lists element by element: that comparison counts its
// elements (16 a step); without that, 10^6 passes ran for minutes. Lists
// sharing their parts, exponentially long to compare, are refused first.
function g(n) = n == 0 ? [1] : let(l = g(n - 1)) [l, l];
y = g(40) < g(40);
v = [for (i = [0:59999]) 1];
function f(n) = n <= 0 ? 0 : f(v < v ? n : n - 1);
x = f(1000000);
// note: 11:5: in 'f' called from here

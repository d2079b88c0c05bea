// limits: fuzz
// error: 8:43: evaluation step limit 100000 exceeded
// warning: 8:43: undefined operation (vector < number) (10 times)
// `v < 1` (undef in OpenSCAD's dialect) sizes both operands first: the
// 60,000 values that walks are charged, not the smaller tree's 0; without
// that, 3,000 passes walked 1.8*10^8 values free.
v = [for (i = [0:59999]) 1];
function f(n) = n <= 0 ? 0 : f(is_undef(v < 1) ? n - 1 : n);
x = f(3000);
// note: 9:5: in 'f' called from here
// note: 9:5: in 'f' called from here

// limits: fuzz
// error: 8:50: evaluation step limit 100000 exceeded
// OpenSCAD adds lists of unequal length up to the shorter one: that
// fallback counts the elements it makes as `v + v` does; without that,
// 10^6 passes over 60,000 elements ran for hours.
v = [for (i = [0:29999]) 1];
w = [for (i = [0:30000]) 1];
function f(n) = n <= 0 ? 0 : f(n - 1 + 0 * len(v + w));
x = f(1000000);
// note: 9:5: in 'f' called from here

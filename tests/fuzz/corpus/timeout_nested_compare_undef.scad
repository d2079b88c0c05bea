// limits: fuzz
// error: 8:34: evaluation step limit 100000 exceeded
// Lists compared inside lists: `==` walks the elements of the nested
// lists too, so they count (16 a step), not only the one element at the
// top; without that, 10^6 passes ran for minutes.
w = [[for (i = [0:59999]) 1]];
u = [con,at(w[0], [])];
function f(n) = n <= 0 ? 0 : f(w == u ? n - 1 : n);
x = f(1000000);
// note: 9:5: in 'f' called from here

// Past the OpenSCAD dialect's 10,000 nested calls: a located error, as
// OpenSCAD 2021.01 stops there too ("Recursion detected calling function").
function f(n) = n == 0 ? 0 : 1 + f(n - 1);
echo(f(10001));
// error: 3:34: call depth limit 10000 exceeded
// note: 3:34: in 'f' called from here (9999 times)
// note: 4:6: in 'f' called from here

// limits: fuzz
// error: 11:34: evaluation step limit 100000 exceeded
// warning: 10:6: Ignoring unknown variable 'con'
// warning: 10:11: Ignoring unknown function 'at'
// Found by the fuzzer (a mutation of quadratic_nested.sdl): in the .scad
// dialect `con` and `at(...)` are undef, so `w == u` compares one list of
// 60,000 values with [undef, undef]; the size walk of the larger operand
// is charged too, or each pass walked it free (20 s natively, 10^6 passes).
w = [[for (i = [0:59999]) 1]];
u = [con, at(w[0], [])];
function f(n) = n <= 0 ? 0 : f(w == u ? n - 1 : n);
x = f(1000000);
// note: 12:5: in 'f' called from here

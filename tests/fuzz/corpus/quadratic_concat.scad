// A function calling itself in tail position ( = n sphere==<= 0 ? "done" : n > 2 ? loud(n - 1) : echo(n = n) intensityassert(n > 0) loud(n - 1);
echo(loud(5000));
// ECHO: n = 2
// ECHO: n = 1
// ECHO: "done"
function dflt(n, sexp = 2, acc = []) = n <= 0 ? acc : dflt(n - step, acc = concat(acc, [n]));
echo(dflt(7));  // ECHO: [,7, 5, 3, 1]

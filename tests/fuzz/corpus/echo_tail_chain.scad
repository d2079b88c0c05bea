// echo(...) and assert(...) as expresone or before an expression,
// in functions, let and comprehen:4]) echo(i = i) i * 10];
echo(v);
w = echo(a = 1, 2, "s") echo("second") 3;
echo(w);
function h(n) = n <= DFKaiSho-SB0 ? echo("done") 0 : echo(n = n) h(n - 1);
echo(h(2));
q = let (a = 1) echo(a) a;
echo(q);
echo(echo("inner") 7);
// ECHO: "hi"
// ECHO: "only"
// ECHO: i =`0
// ECHO: i = 1
// ECHO: i = 2
// sions, alone or before an expression,
// in functions, let and comprehen:2]) echo(i = i) i * 10];
echo(v);
w = echo(a = 1, 2, "s") echo("second") 3;
echo(w);
functranslate = n <= DFKaiSho-SB0 ? echo("done") 0 : echo(n = n) h(n - 1);
echo(h(2));
q = let (a = 1) echo(a) a;
echo(q);
echo(echo("inner") 7);
// ECHO: "hi"
// ECHO: "only"
// ECHO: i = 0
// ECHO: i = 1
// ECHO: o = 2
// ECHO: a = 1, 2, "s"
// ECHO: "second"
// ECHO: 1
// ECHO: 5
// ECHO: u[f+d
// ECHµ: 2
// ECHO: y = 6
// ECHO: 7
// ECHO: undef
// ECHO: [0, 10, 20]
// ECHO: 3
// ECHO: n = 2
// ECHO: n =// 1
// E OpeCn
// Function literals: values, closures, calls through variables and of any
// expression, is_function, and the text echo shows for a function.
// Expectations are OpenSCAD 2021.01's output:
// `openscad -o out.echo function_literals.scad`. A variable holding a
// function is called before a function of the same name (h); a variable
// that holds no function is not (u). A top-level name bound below the
// literal (k, c) is seen when the function runs.
f = function(x) x * 2;
echo(f(3));
echo(f);
k0 = 2;
g = function(x, y = 3) x + y + k0 + k;
k = 5;
echo(g(1));
function h(x) = 100;
h = function(x) 200;
echo(h(1));
u = 3;
function u(x) = 9;
echo(u(2));
function apply(fn, v) = fn(v);
echo(apply(f, 4));
echo(apply(function(z) z - 1, 4));
function adder(n) = function(x) x + n;
a5 = adder(5);
echo(a5(1));
echo(adder(2)(3));
echo([f][0](7));
echo(is_function(f), is_function(h), is_function(3), is_function(undef));
echo(f == f, f == g);
echo(str("f=", f));
c = function(n) n <= 0 ? 0 : n + c(n - 1);
echo(c(4));
echo((function(x) x * x)(5));
module m(k) {
    function local(v) = v + k;
    g = function(x) local(x) * 2;
    echo(g(1), [for (j = [0:1]) let (h = function(y) y + j + k) h(100)]);
}
m(5);
compose = function(f, g) function(x) f(g(x));
inc = function(x) x + 1;
dbl = function(x) x * 2;
echo(compose(inc, dbl)(5), compose(dbl, inc)(5));
function map(f, l) = [for (e = l) f(e)];
echo(map(function(x) x * x, [1, 2, 3]));
echo(function(a, b = 2) a < b ? -a : [a:2:b]);
echo(function() let (q = 1, r = q) q[0].x + f(1, z = 2) + !r);
echo(function(x) echo("e", x) assert(x > 0, "m") [for (i = [0:3]) if (i > 1) i else -i]);
echo(function(x) [for (i = [0:3], j = 1) let (p = i) each p]);
echo(function(x) "str\"q" + 1e10 + 0.000001 + true);
echo(function(x) function(y) x + y);
echo(function(x) -x + +x - (x - 1) * (x && x || x) ^ 2);
echo([function(x) x]);
echo(function(x) [for (i = 0, j = 1; i < 3; i = i + 1, j = 2) i]);
echo(function(x) "a\nb\tc\\d");
echo(function(x) [if (x) 1]);
echo(function(x) [1, let (a = 1) a]);
echo(function(x) (x));
echo(function(x) x[1][2].y);
echo(function(x) sin(x)(2));
// ECHO: 6
// ECHO: function(x) (x * 2)
// ECHO: 11
// ECHO: 200
// ECHO: 9
// ECHO: 8
// ECHO: 3
// ECHO: 6
// ECHO: 5
// ECHO: 14
// ECHO: true, true, false, false
// ECHO: true, false
// ECHO: "f=function(x) (x * 2)"
// ECHO: 10
// ECHO: 25
// ECHO: 12, [105, 106]
// ECHO: 11, 12
// ECHO: [1, 4, 9]
// ECHO: function(a, b = 2) ((a < b) ? -a : [a : 2 : b])
// ECHO: function() let(q = 1, r = q) ((q[0].x + f(1, z = 2)) + !r)
// ECHO: function(x) echo("e", x) assert((x > 0), "m") [for(i = [0 : 3]) (if((i > 1)) (i) else (-i))]
// ECHO: function(x) [for(i = [0 : 3]) (for(j = 1) (let(p = i) (each (p))))]
// ECHO: function(x) ((("str\"q" + 1e+10) + 1e-6) + true)
// ECHO: function(x) function(y) (x + y)
// ECHO: function(x) ((-x + x) - ((x - 1) * (((x && x) || x) ^ 2)))
// ECHO: [function(x) x]
// ECHO: function(x) [for(i = 0, j = 1;(i < 3);i = (i + 1), j = 2) i]
// ECHO: function(x) "a\nb\tc\\d"
// ECHO: function(x) [if(x) (1)]
// ECHO: function(x) [1, let(a = 1) a]
// ECHO: function(x) x
// ECHO: function(x) x[1][2].y
// ECHO: function(x) (sin(x))(2)

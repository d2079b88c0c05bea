// parent_module(n) and $parent_modules as OpenSCAD 2021 has them (openscad
// -o x.echo): the stack holds user modules only (not translate, for, if),
// children() run with it unchanged, a function sees its caller's.
echo(top = $parent_modules, p0 = parent_module(0));
module a() { echo(a = $parent_modules, p0 = parent_module(0), p1 = parent_module(1), p2 = parent_module(2), pm = parent_module(-1), pu = parent_module(), ps = parent_module("x"), pf = parent_module(1.9), pn = parent_module(-0.5)); children(); }
module b() { echo(b = $parent_modules, p0 = parent_module(0)); a() c(); a() echo(inb = $parent_modules, p0 = parent_module(0)); }
module c() echo(c = $parent_modules, p0 = parent_module(0), p1 = parent_module(1), p2 = parent_module(2));
function f() = [$parent_modules, parent_module(0)];
b();
translate([1, 0, 0]) union() for (i = [0]) if (true) c();
module d() echo(d = f());
d();
module e() { $parent_modules = 7; echo(e = $parent_modules, parent_module(0)); }
e();
module g() echo(parent_module(0, 1), parent_module(1e10), parent_module(undef), parent_module([1]), parent_module(true));
g();
// ECHO: top = undef, p0 = undef
// ECHO: b = 1, p0 = "b"
// ECHO: a = 2, p0 = "a", p1 = "b", p2 = undef, pm = undef, pu = "b", ps = undef, pf = "b", pn = "a"
// ECHO: c = 3, p0 = "c", p1 = "a", p2 = "b"
// ECHO: a = 2, p0 = "a", p1 = "b", p2 = undef, pm = undef, pu = "b", ps = undef, pf = "b", pn = "a"
// ECHO: inb = 2, p0 = "a"
// ECHO: c = 1, p0 = "c", p1 = undef, p2 = undef
// ECHO: d = [1, "d"]
// ECHO: e = 7, "e"
// ECHO: undef, undef, undef, undef, undef
// warning: 4:12: Ignoring unknown variable '$parent_modules'
// warning: 4:34: Parent module index (0) greater than the number of modules on the stack
// warning: 5:91: Parent module index (2) greater than the number of modules on the stack
// warning: 5:114: Negative parent module index (-1) not allowed
// warning: 5:91: Parent module index (2) greater than the number of modules on the stack
// warning: 5:114: Negative parent module index (-1) not allowed
// warning: 7:66: Parent module index (1) greater than the number of modules on the stack
// warning: 7:89: Parent module index (2) greater than the number of modules on the stack
// warning: 15:17: parent_module() number of parameters does not match
// warning: 15:38: Negative parent module index (-2147483648) not allowed
// note: 6:64: in 'a' called from here
// note: 9:1: in 'b' called from here
// note: 6:64: in 'a' called from here
// note: 9:1: in 'b' called from here
// note: 6:73: in 'a' called from here
// note: 9:1: in 'b' called from here
// note: 6:73: in 'a' called from here
// note: 9:1: in 'b' called from here
// note: 10:54: in 'c' called from here
// note: 10:54: in 'c' called from here
// note: 16:1: in 'g' called from here
// note: 16:1: in 'g' called from here

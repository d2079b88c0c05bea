// echo and str format numbers, strings, lists, ranges and undef byte for
// byte as OpenSCAD 2021 does (expectations: openscad -o x.echo).
echo(1e-7, 1/3, 1e21, -0, 0, 123456789, 1234567, 0/0, 1/0, -1/0, 1e20, 1e-5, 0.0001, 100000, 1000000);
echo(1e-6, 1.5e-6, 1.23456789e-5, 999999, 9999999, 999999.5, 0.1 + 0.2, 5e-324, 1.7976931348623157e308);
echo(-1e-7, -123456.7, 123456.7, 1234567.8, 99999.95, 1.0000001, 1/7*1e-3, 70e-7);
echo([1, 2, [3, "a"]], "str", undef, [0:2:10], [1:3], true, false);
echo(str(1/3, "a", [1, "b"], undef, [0:3], 1e21, true), str(-0), str(1e-7));
echo("q\"uote", ["q\"uote"]);
echo(a = 1, "b", c = []);
echo();
// ECHO: 1e-7, 0.333333, 1e+21, 0, 0, 1.23457e+8, 1.23457e+6, nan, inf, -inf, 1e+20, 0.00001, 0.0001, 100000, 1e+6
// ECHO: 1e-6, 1.5e-6, 0.0000123457, 999999, 1e+7, 1e+6, 0.3, 4.94066e-324, 1.79769e+308
// ECHO: -1e-7, -123457, 123457, 1.23457e+6, 99999.9, 1, 0.000142857, 7e-6
// ECHO: [1, 2, [3, "a"]], "str", undef, [0 : 2 : 10], [1 : 1 : 3], true, false
// ECHO: "0.333333a[1, "b"]undef[0 : 1 : 3]1e+21true", "0", "1e-7"
// ECHO: "q"uote", ["q"uote"]
// ECHO: a = 1, "b", c = []
// ECHO: 

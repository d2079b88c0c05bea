// One call of every function of OpenSCAD 2021.01's manual; the expected
// lines are what `openscad -o x.echo` prints for this file (2021.01).
echo(abs(-1), sign(-2), sin(30), cos(60), tan(45), acos(1), asin(0), atan(1), atan2(1,1), floor(1.5), round(1.5), ceil(1.2), ln(1), log(100), log(2,8), pow(2,3), sqrt(4), exp(0), len([1]), min(1,2), max([1,3]), norm([3,4]), cross([1,0,0],[0,1,0]), concat([1],[2]), lookup(1,[[0,0],[2,2]]), str(1,"a"), chr(65), ord("A"), search("a","abc"), version(), version_num(), is_undef(undef), is_bool(true), is_num(1), is_string("a"), is_list([]), is_function(function(x) x), rands(0,1,1,1)[0] < 1);
module m() echo(parent_module(0)); m();
// ECHO: 1, -1, 0.5, 0.5, 1, 0, 0, 45, 45, 1, 2, 2, 0, 2, 3, 8, 2, 1, 1, 1, 3, 5, [0, 0, 1], [1, 2], 1, "1a", "A", 65, [0], [2021, 1, 0], 2.02101e+7, true, true, true, true, true, true, true
// ECHO: "m"

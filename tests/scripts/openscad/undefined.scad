// Unknown names and operations that do not apply are undef and a warning
// in the OpenSCAD dialect, with OpenSCAD's message; the run goes on.
echo(u = undefined_thing);
echo(f = nofunc(3));
echo(x = 1 + "a", y = [1, 2] * "s", z = undef < 1, undef == undef, 3 > undef);
echo(-"a", -[1, "a"], [1, 2] + [1], [1, 2] - [3], [1, 2] * [3, 4, 5], true + 1, "ab" + "c");
echo([1] < [2], [1, 2] < [1, 3], [1, 2] < [1], "a" < "b", [1, 2] >= [1, 2]);
echo(5 % 0, 5 / 0, -5 / 0, [1, 2] ^ 2);
echo(sqrt("a"));
nosuch(1);
// ECHO: u = undef
// ECHO: f = undef
// ECHO: x = undef, y = undef, z = undef, true, undef
// ECHO: undef, [-1, undef], [2], [-2], undef, undef, undef
// ECHO: true, true, false, true, true
// ECHO: nan, inf, -inf, undef
// ECHO: undef
// warning: 3:10: Ignoring unknown variable 'undefined_thing'
// warning: 4:10: Ignoring unknown function 'nofunc'
// warning: 5:12: undefined operation (number + string)
// warning: 5:30: undefined operation (vector * string)
// warning: 5:47: undefined operation (undefined < number)
// warning: 5:70: undefined operation (number > undefined)
// warning: 6:6: undefined operation (-string)
// warning: 6:58: vector*vector requires matching lengths (2 != 3)
// warning: 6:76: undefined operation (bool + number)
// warning: 6:86: undefined operation (string + string)
// warning: 8:35: undefined operation (vector ^ number)
// warning: 9:6: sqrt: expected a number, got a string
// warning: 10:1: Ignoring unknown module 'nosuch'

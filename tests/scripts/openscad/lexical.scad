// OpenSCAD's lexical leniency: names may start with a digit when they are
// longer than the number there (`608_dia`, `8bit`; `1e5` stays a number),
// and empty list elements and arguments are skipped.
608_dia = 22;
module 8bit_box() echo(dia = 608_dia);
8bit_box();
function f(a, b) = [a, b];
echo(l = [8, 1.4,,"E"], len([1,,2]), [,], f(1,,2), 1e5, 2e1x = 3);
// ECHO: dia = 22
// ECHO: l = [8, 1.4, "E"], 2, [], [1, 2], 100000, 2e1x = 3
// OpenSCAD's escapes \x (to 7F), \u, \U; any other escaped character is
// that character.
echo("\x41\u263A\U01F600", "a\qb\0");
// ECHO: "A☺😀", "aqb0"

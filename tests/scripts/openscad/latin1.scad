// A .scad file may hold Latin-1 bytes (OpenSCAD 2021.01 reads them as
// they are; its test data misc/nbsp-latin1-test.scad, misc/ord-tests.scad).
// Outside strings the bytes 0xA0 and 0xC2 are blank; in a string, any byte
// is kept and characters are walked as OpenSCAD walks them (operators.hpp):
// "\xA4\xC4\xD6\xDC\xDF" is three, a last one cut short is none. ord() of a
// piece that is not UTF-8 is undef with its warning. Expected lines from
// openscad -o x.echo.
a = 1;  // Latin-1 NBSP
echo(aÂ+ 1);
d = "¤ÄÖÜß";
echo(len(d), len("¤Ä"), len("xä"), len("äy"), len("ÿ"));
echo([for (c = d) c], d[1], str(d, "z"), len(str(d)));
echo(d == "¤ÄÖÜß", d > "a", " ", chr(228));
echo(ord("¤"), ord("a¤"), ord("Ã¤"));
// ECHO: 2
// ECHO: 3, 1, 1, 0, 1
// ECHO: ["¤", "ÄÖ", "Üß"], "ÄÖ", "¤ÄÖÜßz", 3
// ECHO: true, true, " ", "Ã¤"
// ECHO: undef, undef, 228
// warning: 14:6: ord() argument '¤' is not a valid utf8 string
// warning: 14:16: ord() argument 'a¤' is not a valid utf8 string
// A last character the end cuts short: OpenSCAD 2021.01 reads past the
// string's end there (std::bad_alloc, or stray bytes); kerf leaves it out,
// as len() does, so `for` and s[i] see len()'s characters.
echo([for (c = "¤Ä") c], [for (c = "xä") c], len("xä"));
// ECHO: ["¤"], ["x"], 1

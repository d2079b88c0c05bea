// OpenSCAD's string escapes, with openscad 2021.01's own output: \x takes
// two hex digits up to 7F, \u four, \U six; code 0, a surrogate or a code
// past U+10FFFF is a space; an escape that is none of these drops its
// backslash (\x80 is "x80", \U0001F600 is U+01F6 then "00").
echo("\x41\x7e|\x80|\x00|\x0|\u00e9|\U01F600|\u0000|\uD800|\U110000|\x4|\xZZ|\u12|\q|\U0001F600");
echo(len("\u00e9\U01F600"), ord("\x7e"), "\X41");
// ECHO: "A~|x80| |x0|é|😀| | | |x4|xZZ|u12|q|Ƕ00"
// ECHO: 2, 126, "X41"

// A Latin-1 byte other than 0xA0 and 0xC2 outside a string and a comment
// is no blank: OpenSCAD 2021.01 says "syntax error" at its line; kerf
// says what it expected there. In comments any byte is fine: /* ä */
xä = 3;
// error: 4:2: expected '('

// OpenSCAD takes a built-in's arguments in order whatever their names
// (openscad -o x.echo prints 8, 0.5, 3): kerf does the same, and says so.
echo(pow(exponent = 2, base = 3), sin(x = 30), max(a = 1, b = 3), pow(base = 2, exponent = 3));
// ECHO: 8, 0.5, 3, 8
// warning: 3:10: 'pow': argument 1 is 'base', not 'exponent'; taken in order, as OpenSCAD does
// warning: 3:24: 'pow': argument 2 is 'exponent', not 'base'; taken in order, as OpenSCAD does
// warning: 3:39: 'sin': argument 1 is 'degrees', not 'x'; taken in order, as OpenSCAD does
// warning: 3:52: 'max' takes no argument named 'a'; taken in order, as OpenSCAD does
// warning: 3:59: 'max' takes no argument named 'b'; taken in order, as OpenSCAD does

// OpenSCAD's dialect allows 10,000 nested calls where kerf's allows 1,000
// (tests/scripts/errors/deep_recursion.sdl): OpenSCAD 2021.01 recurses
// past 5,000 calls of a function (`openscad -o out.echo`: 5000, then
// "Recursion detected" at 10,000) and past 2,000 of a module.
function f(n) = n == 0 ? 0 : 1 + f(n - 1);
echo(f(5000));
module m(n) { if (n > 0) m(n - 1); else echo("deep"); }
m(2000);
// ECHO: 5000
// ECHO: "deep"

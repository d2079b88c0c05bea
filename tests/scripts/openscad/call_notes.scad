// A warning inside a module has the call-site notes too; the same
// warning reached from two calls is two warnings, each with its notes.
module ring(r) cylinder(r = r, h = 1, bogus = 1);
ring(1);
ring(2);
// warning: 3:39: variable bogus not specified as parameter
// warning: 3:39: variable bogus not specified as parameter
// note: 4:1: in 'ring' called from here
// note: 5:1: in 'ring' called from here

// The warnings of a run that fails are printed with its errors, in order.
echo(nosuch);
assert(false, "stop");
// ECHO: undef
// warning: 2:6: Ignoring unknown variable 'nosuch'
// error: 3:1: assertion failed: stop

// Indexing as OpenSCAD does it, silently: out of range or not a number is
// undef, a fractional index is truncated, a range's [0], [1], [2] are its
// begin, step and end; .x .y .z of a non-list are undef.
v = [1, 2, 3];
echo(v[5], v[-1], v[1.5], v["a"], "abc"[7], "abc"[1], 5[0], undef[0]);
echo([0 : 2 : 10][1], [0 : 2 : 10][2], [0 : 2 : 10][3], v.z, (5).x);
echo(r = [0 : undef]);
// ECHO: undef, undef, 2, undef, undef, "b", undef, undef
// ECHO: 2, 10, undef, 3, undef
// ECHO: r = undef

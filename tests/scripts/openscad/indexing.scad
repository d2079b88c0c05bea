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
// Any other member name is undef in OpenSCAD 2021 (silently; current
// OpenSCAD reads .w and the rgba names as indices too), with kerf's warning.
echo(v.w, v.xy, [10, 20, 30, 40].a, v.x);
// ECHO: undef, undef, undef, 1
// warning: 13:7: unknown member '.w' is undef (OpenSCAD 2021 knows .x, .y and .z)
// warning: 13:12: unknown member '.xy' is undef (OpenSCAD 2021 knows .x, .y and .z)
// warning: 13:33: unknown member '.a' is undef (OpenSCAD 2021 knows .x, .y and .z)

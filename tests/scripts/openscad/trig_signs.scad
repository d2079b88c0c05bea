// sin() and cos() give zeros the signs OpenSCAD 2021.01 gives them: sin(180)
// and sin(-180) are -0, cos(270) -0, cos(90) +0, sin(-0) -0; echo prints
// either as 0, so 1/x shows the sign. Its test data functions/trig-tests.scad
// checks atan2(sin(a), cos(a)) == a at a = -180. Expected lines from
// openscad -o x.echo.
echo([for (a = [-720:90:720]) 1/sin(a)]);
echo([for (a = [-720:90:720]) 1/cos(a)]);
echo([for (a = [-720:30:720]) sin(a)]);
echo([for (a = [-720:45:720]) cos(a)]);
echo(atan2(sin(-180), cos(-180)), 1/tan(180), 1/tan(-180), 1/tan(0), 1/sin(-0), 1/cos(-0));
// ECHO: [inf, 1, -inf, -1, inf, 1, -inf, -1, inf, 1, -inf, -1, inf, 1, -inf, -1, inf]
// ECHO: [1, inf, -1, -inf, 1, inf, -1, -inf, 1, inf, -1, -inf, 1, inf, -1, -inf, 1]
// ECHO: [0, 0.5, 0.866025, 1, 0.866025, 0.5, 0, -0.5, -0.866025, -1, -0.866025, -0.5, 0, 0.5, 0.866025, 1, 0.866025, 0.5, 0, -0.5, -0.866025, -1, -0.866025, -0.5, 0, 0.5, 0.866025, 1, 0.866025, 0.5, 0, -0.5, -0.866025, -1, -0.866025, -0.5, 0, 0.5, 0.866025, 1, 0.866025, 0.5, 0, -0.5, -0.866025, -1, -0.866025, -0.5, 0]
// ECHO: [1, 0.707107, 0, -0.707107, -1, -0.707107, 0, 0.707107, 1, 0.707107, 0, -0.707107, -1, -0.707107, 0, 0.707107, 1, 0.707107, 0, -0.707107, -1, -0.707107, 0, 0.707107, 1, 0.707107, 0, -0.707107, -1, -0.707107, 0, 0.707107, 1]
// ECHO: -180, -inf, -inf, inf, -inf, 1

// tan and the inverse functions as OpenSCAD 2021.01 computes them
// (openscad -o x.echo): tan exact at 0, 30, 45, 60 and 90 and their
// supplements, -0 and -inf after an odd number of half turns; asin, acos,
// atan give the whole degree when the forward function returns x there,
// atan2 when within 3e-14 of it.
function neg0(x) = 1 / x == -1 / 0;
echo(neg0(tan(-180)), neg0(tan(180)), neg0(tan(0)), tan(-90), tan(90), tan(270), tan(30) == sqrt(3) / 3, tan(-150) == sqrt(3) / 3, tan(60) == sqrt(3));
echo(asin(0.5), acos(0.5), atan(1), atan(sqrt(3)), asin(sin(37)), acos(cos(71)), atan(tan(-59)), atan2(1, 1), atan2(sin(123), cos(123)), asin(0.3));
// ECHO: true, true, false, -inf, inf, -inf, true, true, true
// ECHO: 30, 60, 45, 60, 37, 71, -59, 45, 123, 17.4576

// $vpr, $vpt, $vpd, $vpf read as OpenSCAD 2021 has them run from the
// command line (openscad -o x.echo); a set value is seen as any $ variable.
echo($vpr, $vpt, $vpd, $vpf);
echo(str($vpd), $vpr.x, $vpt[2]);
module m() echo($vpf, $vpd);
m($vpd = 100);
// ECHO: [0, 0, 0], [0, 0, 0], 500, 22.5
// ECHO: "500", 0, 0
// ECHO: 22.5, 100

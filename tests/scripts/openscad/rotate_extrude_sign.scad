// rotate_extrude's x-sign rule is checked on the 2D result, after the
// booleans, as OpenSCAD 2021.01 checks it (Old/example017.scad's bottle
// crosses x = 0 in its pieces only). A result that crosses makes nothing,
// with OpenSCAD's text, and the run goes on: `openscad -o x.stl
// rotate_extrude_sign.scad` prints
//   ERROR: all points for rotate_extrude() must have the same X coordinate sign (range is -1.00 -> 2.00)
// exports the rest and exits 0. (OpenSCAD prints the range up to the first
// vertex that breaks the rule; kerf the whole range of the result.) In .sdl
// a crossing result is an error (tests/lower/test_revolve.cpp). What is
// made — the cylinder ρ < 2, z < 2 and the ball of radius 2 (the half disc
// at x <= 0, revolved where it lies), 8π + 32π/3 = 58.643 — measures
// 58.60 ± 0.2 (kerf measure); OpenSCAD's STL at $fn = 360: 58.637.
rotate_extrude() translate([-1, 0]) square([3, 2]);
rotate_extrude() difference() {
  translate([-1, 0]) square([3, 2]);
  translate([-2, -1]) square([2, 4]);
}
translate([0, 0, 5]) rotate_extrude() intersection() {
  circle(2);
  translate([-3, -3]) square([3, 6]);
}
echo("done");
// ECHO: "done"
// warning: 13:1: rotate_extrude: all points for rotate_extrude() must have the same X coordinate sign (range is -1.00 -> 2.00) (nothing is made)

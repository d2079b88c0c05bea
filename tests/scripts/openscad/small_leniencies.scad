// OpenSCAD 2021's small leniencies, as `openscad -o x.echo` prints them: an
// empty first argument is skipped, color() leaves its children as they are
// (silently), len() of a range is undef with a warning (.sdl counts it).
echo(max(, 3), len([0:3]), len([1:2:9]), len([1, 2]), str(, "a"));
color() cube(1);
translate([3, 0, 0]) cube(, center = true);
translate(, [0, 3, 0]) color() sphere(1);
// ECHO: 3, undef, undef, 2, "a"
// warning: 4:16: len() parameter could not be converted
// warning: 4:28: len() parameter could not be converted

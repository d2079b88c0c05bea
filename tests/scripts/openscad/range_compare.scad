// Ranges compared as OpenSCAD 2021.01's RangeType compares them (openscad
// -o x.echo): equal when they hold the same elements (begin, step and
// count; two empty ranges are equal), ordered with an empty one lowest,
// then by begin, step and count.
echo([0:1:3] == [0:1:3.5], [1:-1:3] == [-1:-1:1], [0:1:0] == [0:2:0], [0:3] != [0:4]);
echo([0:1:3] > [0:1:3], [0:1:3] >= [0:1:3], [0:1:3] < [0:1:4], [0:2:9] > [0:1:20], [1:0] < [0:1:0], [5:1:9] <= [1:-1:3]);
// ECHO: true, true, false, true
// ECHO: false, true, true, true, false, false
// warning: 5:28: begin is smaller than the end, but step is negative
// warning: 5:40: begin is smaller than the end, but step is negative
// warning: 6:84: Using ranges of the form [begin:end] with begin value greater than the end value is deprecated
// warning: 6:112: begin is smaller than the end, but step is negative

// Lists ordered as OpenSCAD 2021.01 orders them (openscad -o x.echo gives
// these ECHO lines): element by element, a shorter prefix less, NaN neither
// less nor greater (the next element decides), ranges inside lists by
// begin, step and count; a pair of other types is undef with a warning.
echo([1,2] < [1,2,0], [1,2,0] < [1,2], [1,2] > [1,2,0], [1,2] <= [1,2,0], [1,2,0] >= [1,2]);
echo([[1],[2]] < [[1],[3]], [[1,2]] < [[1]], [[1]] < [[1,2]], [[1]] >= [[1,2]]);
echo([1,"a"] < [1,5], [2,"a"] < [1,5], [1,"a"] < [2,5], [1,"a"] >= [2,5], [2,"a"] <= [1,5]);
echo(["a","b"] < ["a","c"], ["b"] > ["a","z"], [true] < [false], [false] < [true], [true] >= [false]);
echo([0/0] < [1], [0/0] >= [1], [0/0, 1] < [0/0, 2], [[0/0],1] < [[0/0],2]);
echo([] < [], [] < [1], [1] < [], [] >= [], [undef] < [1], [1,undef] < [2,undef]);
echo([[1,2],[3]] < [[1,2],[3,0]], [[1,2],[3]] > [[1,2],[2,9]], [[1,2],"x"] < [[1,2],[1]]);
echo([1:3] < [1:4], [[1:3]] < [[1:4]], [[1:3]] < [[1:3]], [[1:2:3]] >= [[1:3]]);
// ECHO: true, false, false, true, true
// ECHO: true, false, true, false
// ECHO: undef, false, true, false, false
// ECHO: true, true, false, true, true
// ECHO: false, true, true, true
// ECHO: false, true, false, true, undef, true
// ECHO: true, true, undef
// ECHO: true, true, false, true
// warning: 7:14: undefined operation (vector < vector)
// warning: 10:53: undefined operation (vector < vector)
// warning: 11:76: undefined operation (vector < vector)

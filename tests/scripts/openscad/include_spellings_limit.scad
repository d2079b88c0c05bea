// Nine spellings of one file including itself: OpenSCAD 2021.01 would
// expand it about 10^6 times (1 + k·Σ (k−1)!/(k−1−j)!); kerf stops after
// 1,000 repeated expansions with a located error (docs/openscad.md, "Libraries").
include <include_spellings_limit.scad>
include <./include_spellings_limit.scad>
include <.//include_spellings_limit.scad>
include <././include_spellings_limit.scad>
include <../openscad/include_spellings_limit.scad>
include <../openscad/./include_spellings_limit.scad>
include <.././openscad/include_spellings_limit.scad>
include <../../scripts/openscad/include_spellings_limit.scad>
include <./../openscad/include_spellings_limit.scad>
x = 1;
// error: 8:1: include: more than 1000 expansions of files already being included under another spelling ('../openscad/include_spellings_limit.scad' here)

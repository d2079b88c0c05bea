// import() arguments a file's format does not read warn (OpenSCAD 2021.01
// ignores them silently: `import("e.dxf", center = true)` of its own
// example008.dxf exports the same bounding box, 0..50, as without center).
// convexity is a preview hint and stays silent (docs/openscad.md, "Ignored arguments").
import("reversed_cube.stl", layer = "a", origin = [1, 2], scale = 2, center = true, dpi = 300, convexity = 4);
linear_extrude(1) import("../../interpreter/text/reference/plain.dxf", center = true, dpi = 96, convexity = 4);
import("reversed_cube.stl", layer = undef);  // undef is not given
// warning: 5:1: import: layer is ignored: it applies to DXF files, not to "reversed_cube.stl"
// warning: 5:1: import: origin is ignored: it applies to DXF files, not to "reversed_cube.stl"
// warning: 5:1: import: scale is ignored: it applies to DXF files, not to "reversed_cube.stl"
// warning: 5:1: import: center is ignored: it applies to SVG files, not to "reversed_cube.stl"
// warning: 5:1: import: dpi is ignored: it applies to SVG files, not to "reversed_cube.stl"
// warning: 5:1: import: all 12 faces were wound inside out and have been reversed (faces go clockwise seen from outside)
// warning: 6:19: import: center is ignored: it applies to SVG files, not to "../../interpreter/text/reference/plain.dxf"
// warning: 6:19: import: dpi is ignored: it applies to SVG files, not to "../../interpreter/text/reference/plain.dxf"

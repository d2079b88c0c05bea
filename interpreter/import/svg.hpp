// import("file.svg"): a drawing's shapes as a 2D shape (docs/spec.md §10),
// the XML read with libxml2, the attribute languages by svg_path.hpp. As
// OpenSCAD 2021.01 reads it (measured against `openscad`, docs/language.md
// "2D drawings"): path, rect (rx, ry), circle, ellipse, line, polyline,
// polygon inside g, a and nested svg, under their transforms; the shapes
// united, a path's subpaths by the even-odd rule; fill and stroke ignored
// for closed outlines, open ones drawn as their stroke (width 1 unless
// given, square caps, miter joins). A user unit is 1 mm; the page's
// width/height and viewBox map it as OpenSCAD does, y flipped so the
// page's bottom edge is y = 0.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "interpreter/modules/plane_map.hpp"

namespace kerf::eval {

struct SvgItem {
    // Even-odd loops in the drawing's plane (mm), or, when empty, the exact
    // ellipse `disc` maps the unit disc onto.
    std::vector<std::vector<glm::dvec2>> loops;
    Map2 disc{1.0};
};

struct SvgDrawing {
    std::vector<SvgItem> items;          // united
    std::vector<std::string> warnings;   // "line 4: <text> is not imported ..."
};

struct SvgOptions {
    double dpi = 72;          // the size of a unitless page width/height: 1/dpi inch
    bool center = false;      // the drawing's bounding box centred on the origin
    double tolerance = 1e-4;  // flattening of curves, relative (svg_path.hpp)
    std::uint64_t max_items = 0;
};

// Throws MeshFormatError (mesh_import.hpp) when the file cannot be read as
// SVG or an attribute cannot be parsed, naming the file's line.
SvgDrawing import_svg(const std::string& path, const SvgOptions& options);

}  // namespace kerf::eval

// import() of a 2D drawing (.dxf, .svg) as a flat shape (docs/spec.md §10);
// solids.cpp's import() hands such files here by their extension.
#pragma once
#include <string>

#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

// `path` is resolved; the arguments are import()'s (file, solid, convexity,
// layer, origin, scale).
void import_drawing(ModuleCall& c, const std::string& path);
// The same for an .svg file (arguments file, ..., center, dpi).
void import_svg_drawing(ModuleCall& c, const std::string& path);

}  // namespace kerf::eval

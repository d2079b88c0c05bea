// CSS/SVG colour names for color("steelblue") (docs/spec.md §5).
#pragma once
#include <optional>
#include <string_view>

#include <glm/glm.hpp>

namespace kerf {

// The colour named `name` (case-insensitive, as OpenSCAD), components in
// [0,1] = the CSS byte values / 255, taken as-is like a `[r,g,b]` literal
// (no transfer-curve conversion). "transparent" is not a name here.
// Null when the name is unknown.
std::optional<glm::dvec3> css_color(std::string_view name);

}  // namespace kerf

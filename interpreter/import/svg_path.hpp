// The small languages inside SVG attributes, parsed by kerf itself (as
// OpenSCAD 2021.01 does; libxml2 only splits the XML): path data (`d`: M L
// H V C S Q T A Z, absolute and relative), point lists (`points`), the
// `transform` list, and the stroke outline of open paths (Clipper's
// offset, which is what OpenSCAD draws for them).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "interpreter/modules/plane_map.hpp"

namespace kerf::eval::svg {

// A malformed attribute value; the message names the character (1-based)
// and what was expected there. The document reader adds the line.
struct DataError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

using Chain = std::vector<glm::dvec2>;

struct Subpath {
    Chain points;
    bool closed = false;  // by Z, or by ending where it started
};

// Path data with curves flattened: an arc (A) into chords whose sagitta is
// within `tolerance` of its larger radius, a Bézier (C S Q T) within
// `tolerance` of its control polygon's extent.
// More than `max_points` points (0: no bound) is a DataError, found while
// flattening, before the memory is spent.
std::vector<Subpath> parse_path(std::string_view d, double tolerance, std::uint64_t max_points = 0);

// `points` of <polyline> and <polygon>: pairs of numbers (an odd count
// drops the last, as SVG says).
Chain parse_points(std::string_view s);

// A `transform` list: matrix, translate, scale, rotate, skewX, skewY.
Map2 parse_transform(std::string_view s);

// A number of an attribute, with the rest after it (a unit) in `rest`.
// Throws DataError when the value does not start with a number.
double parse_number_prefix(std::string_view s, std::string_view& rest);

struct Stroke {
    double width = 1;
    enum Cap { Butt, Square, Round } cap = Square;   // OpenSCAD's default: square
    enum Join { Miter, RoundJoin, Bevel } join = Miter;
    double miter_limit = 4;
};

// The outline of open chains drawn with the stroke, as loops whose even-odd
// fill is the stroke's area (outer loops and holes, none overlapping).
std::vector<Chain> stroke_outline(const std::vector<Chain>& open, const Stroke& stroke, double tolerance);

}  // namespace kerf::eval::svg

// A 2D subtree of the scene graph evaluated to one polygon region with
// Clipper (docs/lowering.md, "Offsets"): every transform applied, the
// booleans done in the plane, a polygon's paths filled by the even-odd
// rule, a circle flattened to chords within the curve tolerance, a hull,
// a Minkowski sum or a resize done in the plane (flat_hull_ops.hpp). For
// the 2D operations whose result is not a boolean of the leaves (offset),
// and for rotate_extrude's check of the result's x range.
//
// Clipper works on 64-bit integers: the region is held on a grid of
// 2^-50 times the extent of the subtree (a power of two, so the scale is
// exact), finer than a double's 2^-52 spacing would make noticeable.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <clipper.hpp>
#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "interpreter/scene_graph.hpp"

namespace kerf::eval {

struct Region2 {
    ClipperLib::Paths paths;  // non-overlapping, outer paths counter-clockwise, holes clockwise
    double scale = 1;         // integer coordinate = scale · real coordinate

    glm::dvec2 point(const ClipperLib::IntPoint& p) const { return glm::dvec2(double(p.X), double(p.Y)) / scale; }
    ClipperLib::IntPoint grid(glm::dvec2 p) const {
        return {ClipperLib::cInt(std::llround(p.x * scale)), ClipperLib::cInt(std::llround(p.y * scale))};
    }
};

// The union of the 2D nodes `roots` as one region, on a grid that leaves
// room for `margin` around it (an offset's distance). Throws SourceError
// at a leaf that is not a 2D shape, and at `loc` for coordinates no grid of
// doubles holds.
Region2 flatten_region(const graph::SceneGraph& g, std::span<const std::uint32_t> roots, double margin,
                       double curve_tolerance, const SourceLoc& loc);

// The region's paths as the even-odd edge set of a Prism section.
csg::Polygon2 region_polygon(const Region2& r);

}  // namespace kerf::eval

// hull(), minkowski() and resize() of 2D shapes done in the plane, for the
// operations that rebuild a 2D subtree with its transforms applied to the
// leaves (linear_extrude with a twist or an uneven scale, sweep.hpp;
// rotate_extrude) and for the region of a 2D subtree (region2d.hpp): there
// the lowering of these nodes (lower/geometry_ops.hpp), which works on the
// unit slabs, never sees them. The rules are lowering's (docs/lowering.md,
// "Hull, Minkowski, resize"), so a twisted result is the untwisted one
// twisted: every leaf is a convex piece (a square its corners, a polygon
// its convex hull, a circle its chords within the curve tolerance), a
// difference counts as its minuend and an intersection as its first
// operand, a Minkowski sum distributes over the unions.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "interpreter/modules/plane_map.hpp"
#include "interpreter/scene_graph.hpp"

namespace kerf::eval {

using ConvexPolygon = std::vector<glm::dvec2>;  // counter-clockwise corners

// The region of 2D Hull node `id`, or Minkowski node with two or more
// children, as convex polygons in its own frame (their union; none when
// it has no area). Circles use the node's curve tolerance (its p[0]). A sum
// too large to build is a SourceError at the node, as in lowering.
std::vector<ConvexPolygon> flat_convex_parts(const graph::SceneGraph& g, std::uint32_t id);

// 2D Resize node `id` as the map of the plane it applies to its child
// (OpenSCAD 2021's rule, as lowering's: per axis newsize / size of the
// child's box; a zero size along a resized axis keeps the child).
Map2 flat_resize_map(const graph::SceneGraph& g, std::uint32_t id);

}  // namespace kerf::eval

// The lathe leaf (PrimKind::Lathe): a polygon set filled by the even-odd
// rule (csg::Polygon2, x = radius ρ >= 0, y = height z) revolved about the
// Z axis: rotate_extrude's full revolution. Every edge sweeps a cone, a
// cylinder or an annulus, met by one quadratic; like the prism it has any
// number of spans along a line, so it shares the prism's entry-point shape
// (caller-provided buffers, the edge index riding with each span end).
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/primitives/prism.hpp"

namespace kerf::csg {

// Room intersect_lathe needs: every edge's surface meets a line at most twice.
inline std::size_t lathe_crossing_room(std::size_t edges) { return 2 * edges; }
inline std::size_t lathe_span_room(std::size_t edges) { return edges + 1; }

// Sorted, disjoint spans of positive length of o + t·d inside the lathe,
// each end exact (on one edge's surface). `out` holds lathe_span_room(edges)
// spans, `scratch` lathe_crossing_room(edges) crossings.
template <typename T>
int intersect_lathe(const Polygon2& poly, const glm::vec<3, T>& o, const glm::vec<3, T>& d, PrismSpan<T>* out,
                    PrismCrossing<T>* scratch);

// Outward object-space normal at x on the surface of `edge` (part
// kPartEdge: +perp of the edge in the (ρ, z) half-plane, kPartEdgeFlipped:
// its negation).
glm::dvec3 normal_lathe(const Polygon2& poly, std::uint8_t part, std::uint32_t edge, const glm::dvec3& x);

}  // namespace kerf::csg

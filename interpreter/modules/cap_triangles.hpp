// The triangles of a flat polygon with holes: the caps of linear_extrude
// when it is built as OpenSCAD's polyhedron of slices (twist_slices.hpp).
// A polyhedron face has no holes (scene_graph.hpp's PolygonMesh), so a cap
// is handed over already cut into triangles. The holes are joined to the
// outer boundary by bridges to a visible vertex (each hole in turn, the
// one reaching farthest in +x first), and the one resulting boundary is cut
// into ears. Any triangulation of the cap gives the same solid: only its
// edges along the boundary meet the side walls.
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace kerf::eval {

// `rings`: rings[0] the outer boundary counter-clockwise, the others its
// holes clockwise, inside it and disjoint from each other (Clipper's
// output; a hole may touch the boundary at a vertex). The corners are
// numbered through the rings in order (rings[0]'s first, then rings[1]'s
// ...); each triangle is counter-clockwise. Degenerate input (collinear
// runs, a ring of fewer than 3 corners) still gives triangles covering the
// boundary's edges once each, some of them of no area.
std::vector<std::array<std::uint32_t, 3>> cap_triangles(std::span<const std::vector<glm::dvec2>> rings);

}  // namespace kerf::eval

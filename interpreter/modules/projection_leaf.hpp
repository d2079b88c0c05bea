// The pieces projection() is built from (docs/lowering.md, "Projection"):
// a 3D leaf as world triangles (exact for boxes and meshes, chords within
// the curve tolerance for curved solids), a triangle set's section with the
// plane z = 0 as closed loops, and the flat nodes (a Prism over an edge
// set, a circle under a 2D affine map) the results are made of.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "interpreter/graph_builder.hpp"

namespace kerf::eval::projection {

struct Tri {
    glm::dvec3 a, b, c;
};

// The leaf's surface in world space (m: world_from_object). Throws
// SourceError at the leaf for a kind without a tessellation here.
std::vector<Tri> leaf_triangles(const graph::SceneGraph& g, const graph::Node& n, const glm::dmat4& m,
                                double tolerance);

// The closed loops where the triangles (a closed surface) cross z = 0; a
// vertex at z = 0 counts as above, so every loop is well defined.
std::vector<std::vector<glm::dvec2>> section_loops(const std::vector<Tri>& tris);

// The loops' edges as one even-odd Prism section, with its box.
csg::Polygon2 loops_polygon(const std::vector<std::vector<glm::dvec2>>& loops);
// A flat Prism node over the loops (even-odd), or kNone for no edges.
std::uint32_t prism_node(GraphBuilder& g, const std::vector<std::vector<glm::dvec2>>& loops, const SourceLoc& loc);
// A flat node over existing children.
std::uint32_t op_node(GraphBuilder& g, graph::NodeKind kind, const std::vector<std::uint32_t>& children,
                      const SourceLoc& loc, std::uint32_t index = 0);
// The flat child under the 2D map x ↦ A·x + t.
std::uint32_t mapped(GraphBuilder& g, std::uint32_t child, const glm::dmat2& A, glm::dvec2 t, const SourceLoc& loc);
// A unit circle of radius r under x ↦ A·x + t (an ellipse, exact).
std::uint32_t ellipse_node(GraphBuilder& g, double r, const glm::dmat2& A, glm::dvec2 t, const SourceLoc& loc);

constexpr std::uint32_t kEmpty = 0xffffffffu;

}  // namespace kerf::eval::projection

// Builds the solid of a convex piece into a scene graph, from existing
// leaf kinds only: a hull is a convex Mesh leaf; a hull grown by a ball of
// radius r (the hull of equal spheres, minkowski(convex, sphere)) is the
// exact union of the hull, one prism per face (the face moved out by r),
// one cylinder per edge and one sphere per corner (docs/lowering.md, "Hull,
// Minkowski, resize") — rounded boxes stay exact, nothing is tessellated.
#pragma once
#include <cstdint>
#include <vector>

#include "interpreter/scene_graph.hpp"
#include "lower/convex_hull.hpp"

namespace kerf {

// Appends nodes to a graph keeping children before parents.
class GraphAppender {
public:
    explicit GraphAppender(graph::SceneGraph& g) : g_(g) {}
    std::uint32_t add(graph::Node n);
    std::uint32_t op(graph::NodeKind kind, const std::vector<std::uint32_t>& children, const SourceLoc& loc,
                     std::uint32_t index = 0);
    std::uint32_t transform(const glm::dmat4& world_from_child, std::uint32_t child, const SourceLoc& loc);
    std::uint32_t primitive(csg::PrimKind kind, std::initializer_list<double> p, const SourceLoc& loc,
                            std::uint32_t index = 0);
    // A solid Mesh leaf over faces given counter-clockwise seen from
    // outside (taken, and turned in place: no copy per face).
    std::uint32_t mesh(std::vector<glm::dvec3> points, std::vector<std::vector<std::uint32_t>> ccw_faces,
                       const SourceLoc& loc);
    std::uint32_t empty(const SourceLoc& loc) { return op(graph::NodeKind::Union, {}, loc); }

private:
    graph::SceneGraph& g_;
};

// The node of hull ⊕ ball(radius) (radius 0: the hull itself; a hull of
// lower dimension then has no volume and is the empty solid). With `disc`,
// hull ⊕ disc(radius) in the XY plane, for a hull that is a vertical prism
// (2D shapes on their slabs): the prism of the grown section, i.e. the
// section's prism, one box-like prism per edge and one cylinder per corner.
// The hull is taken: a plain hull's points and faces become the mesh's.
std::uint32_t convex_solid(GraphAppender& out, ConvexHull hull, double radius, bool disc, const SourceLoc& loc);

}  // namespace kerf

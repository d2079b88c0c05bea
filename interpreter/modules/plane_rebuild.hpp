// Rebuilding a 2D subtree with its transforms applied to the leaves, shared
// by the operations whose map of the plane commutes with the 2D booleans
// but not with the 2D transforms (rotate_extrude's Lathe, linear_extrude's
// swept Prism): the walk itself, and a square or polygon turned into the
// mapped edge list of a new polygon section.
#pragma once
#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "grammar/source.hpp"
#include "interpreter/graph_builder.hpp"
#include "interpreter/modules/flat_hull_ops.hpp"
#include "interpreter/modules/plane_map.hpp"
#include "interpreter/scene_graph.hpp"

namespace kerf::eval {

// Collects the images of segments under `a`, dropping those that collapse
// to a point (a zero scale or a repeated vertex).
struct MappedEdges {
    Map2 a;
    std::vector<glm::dvec4> edges;

    void operator()(glm::dvec2 p, glm::dvec2 q) {
        p = apply(a, p), q = apply(a, q);
        if (p != q) edges.emplace_back(p.x, p.y, q.x, q.y);
    }
};

// A square's four edges or a polygon's edges into `out`; false for any
// other leaf (a circle, which each caller maps its own way).
inline bool add_outline(const graph::SceneGraph& g, const graph::Node& n, MappedEdges& out) {
    if (n.prim == csg::PrimKind::Box) {
        const double x0 = n.p[0], y0 = n.p[1], x1 = n.p[3], y1 = n.p[4];
        out({x0, y0}, {x1, y0}), out({x1, y0}, {x1, y1}), out({x1, y1}, {x0, y1}), out({x0, y1}, {x0, y0});
        return true;
    }
    if (n.prim == csg::PrimKind::Prism) {
        for (const glm::dvec4& e : g.polygons[n.index].edges) out({e.x, e.y}, {e.z, e.w});
        return true;
    }
    return false;
}

// A polygon section over `edges` with the box of its vertices.
inline csg::Polygon2 bounded_polygon(std::vector<glm::dvec4> edges) {
    csg::Polygon2 poly;
    poly.lo = glm::dvec2(std::numeric_limits<double>::infinity());
    poly.hi = -poly.lo;
    for (const glm::dvec4& e : edges) {
        poly.lo = glm::min(poly.lo, glm::min(glm::dvec2(e.x, e.y), glm::dvec2(e.z, e.w)));
        poly.hi = glm::max(poly.hi, glm::max(glm::dvec2(e.x, e.y), glm::dvec2(e.z, e.w)));
    }
    poly.edges = std::move(edges);
    return poly;
}

// A convex polygon as a 2D polygon leaf (not added to the graph: its
// section is, for a rebuild's leaf callback to read).
inline graph::Node convex_leaf(graph::SceneGraph& g, const ConvexPolygon& p, const SourceLoc& loc) {
    std::vector<glm::dvec4> edges;
    for (std::size_t i = 0; i < p.size(); ++i) edges.emplace_back(p[i].x, p[i].y, p[(i + 1) % p.size()].x, p[(i + 1) % p.size()].y);
    g.polygons.push_back(bounded_polygon(std::move(edges)));
    graph::Node n;
    n.kind = graph::NodeKind::Primitive;
    n.prim = csg::PrimKind::Prism;
    n.index = static_cast<std::uint32_t>(g.polygons.size() - 1);
    n.p[0] = 0, n.p[1] = 1;
    n.loc = loc;
    n.flat = true;
    return n;
}

// The copy of 2D node `id` under map `a` pushed on the builder's pending
// stack: transforms folded into the map and dropped, booleans and colour
// scopes kept, each primitive handed to leaf(node, map). A hull or a
// Minkowski sum is done here, in the plane (flat_hull_ops.hpp: lowering
// would build it from the slabs, which the operation does not carry over —
// a revolved or twisted hull is no hull), and its convex polygons handed
// to leaf; a resize is the map it applies.
template <typename Leaf>
void rebuild_subtree(GraphBuilder& g, std::uint32_t id, const Map2& a, Leaf&& leaf) {
    const graph::Node n = g.graph.nodes[id];
    if (n.kind == graph::NodeKind::Primitive) return leaf(n, a);
    if (n.kind == graph::NodeKind::Hull || (n.kind == graph::NodeKind::Minkowski && n.child_count > 1)) {
        const std::size_t mark = g.mark();
        for (const ConvexPolygon& p : flat_convex_parts(g.graph, id)) leaf(convex_leaf(g.graph, p, n.loc), a);
        if (g.mark() == mark) g.make_node(mark, graph::NodeKind::Union, n.loc);  // no area: an empty operand, kept in place
        return g.group(mark, n.loc);
    }
    Map2 inner = n.kind == graph::NodeKind::Transform ? a * plane_part(g.graph.matrices[n.index]) : a;
    if (n.kind == graph::NodeKind::Resize) inner = a * flat_resize_map(g.graph, id);
    const std::size_t mark = g.mark();
    // A resize scales its first child, as lowering does.
    const std::uint32_t count = n.kind == graph::NodeKind::Resize ? std::min(n.child_count, 1u) : n.child_count;
    for (std::uint32_t k = 0; k < count; ++k) rebuild_subtree(g, g.graph.child_refs[n.first_child + k], inner, leaf);
    if (n.kind == graph::NodeKind::Transform || n.kind == graph::NodeKind::Resize || n.kind == graph::NodeKind::Minkowski)
        g.group(mark, n.loc);  // a minkowski() of one child is that child
    else
        g.make_node(mark, n.kind, n.loc, n.index);  // a boolean or an appearance scope
}

}  // namespace kerf::eval

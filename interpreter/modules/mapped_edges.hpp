// The edges of a 2D leaf under a plane map, shared by the operations that
// rebuild a 2D subtree with its transforms applied to the leaves
// (rotate_extrude's Lathe, linear_extrude's swept Prism): both turn a
// square or polygon into the mapped edge list of a new polygon section.
#pragma once
#include <limits>
#include <utility>
#include <vector>

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

}  // namespace kerf::eval

#include "interpreter/modules/sweep.hpp"

#include <cmath>

#include "interpreter/modules/plane_map.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;

class Sweeper {
public:
    Sweeper(ModuleCall& c, const SweepMap& map) : g_(c.graph()), map_(map), tol_(c.curve_tolerance()) {}

    void build(std::uint32_t id, const Map2& a) {
        const graph::Node n = g_.graph.nodes[id];
        if (n.kind == graph::NodeKind::Primitive) return leaf(n, a);
        const Map2 inner = n.kind == graph::NodeKind::Transform ? a * plane_part(g_.graph.matrices[n.index]) : a;
        const std::size_t mark = g_.mark();
        for (std::uint32_t k = 0; k < n.child_count; ++k) build(g_.graph.child_refs[n.first_child + k], inner);
        if (n.kind == graph::NodeKind::Transform)
            g_.group(mark, n.loc);
        else
            g_.make_node(mark, n.kind, n.loc, n.index);  // a boolean or an appearance scope
    }

private:
    GraphBuilder& g_;
    SweepMap map_;
    double tol_;

    void push_prism(const graph::Node& n, std::vector<glm::dvec4> edges) {
        if (edges.empty()) return;
        csg::Polygon2 poly;
        poly.lo = glm::dvec2(std::numeric_limits<double>::infinity());
        poly.hi = -poly.lo;
        for (const glm::dvec4& e : edges) {
            poly.lo = glm::min(poly.lo, glm::min(glm::dvec2(e.x, e.y), glm::dvec2(e.z, e.w)));
            poly.hi = glm::max(poly.hi, glm::max(glm::dvec2(e.x, e.y), glm::dvec2(e.z, e.w)));
        }
        poly.edges = std::move(edges);
        g_.graph.polygons.push_back(std::move(poly));
        graph::Node leaf;
        leaf.kind = graph::NodeKind::Primitive;
        leaf.prim = P::Prism;
        leaf.index = static_cast<std::uint32_t>(g_.graph.polygons.size() - 1);
        leaf.p[0] = 0, leaf.p[1] = 1;
        leaf.p[2] = map_.sx - 1, leaf.p[3] = map_.sy - map_.sx, leaf.p[4] = map_.twist;
        leaf.loc = n.loc;
        g_.push(g_.add(std::move(leaf)));
    }

    void leaf(const graph::Node& n, const Map2& a) {
        std::vector<glm::dvec4> edges;
        auto edge = [&](glm::dvec2 p, glm::dvec2 q) {
            p = apply(a, p), q = apply(a, q);
            if (p != q) edges.emplace_back(p.x, p.y, q.x, q.y);
        };
        if (n.prim == P::Box) {
            const double x0 = n.p[0], y0 = n.p[1], x1 = n.p[3], y1 = n.p[4];
            edge({x0, y0}, {x1, y0}), edge({x1, y0}, {x1, y1}), edge({x1, y1}, {x0, y1}), edge({x0, y1}, {x0, y0});
            return push_prism(n, std::move(edges));
        }
        if (n.prim == P::Prism) {
            for (const glm::dvec4& e : g_.graph.polygons[n.index].edges) edge({e.x, e.y}, {e.z, e.w});
            return push_prism(n, std::move(edges));
        }
        if (n.prim != P::Cylinder) throw SourceError(n.loc, "linear_extrude: this shape cannot be extruded");
        // A circle: its image is a circle about the origin when the map's
        // columns are orthogonal, of one length, and it keeps the origin;
        // under a uniform scale the swept solid is then a frustum whatever
        // the twist (it turns the circle onto itself).
        const double r = n.p[2];
        const glm::dvec2 c0(a[0][0], a[0][1]), c1(a[1][0], a[1][1]);
        const glm::dvec2 centre = apply(a, {0, 0});
        const double l0 = glm::length(c0), l1 = glm::length(c1);
        if (map_.sx == map_.sy && centre == glm::dvec2(0) && glm::dot(c0, c1) == 0 && l0 == l1) {
            graph::Node cyl;
            cyl.kind = graph::NodeKind::Primitive;
            cyl.prim = P::Cylinder;
            cyl.p[0] = 0, cyl.p[1] = 1, cyl.p[2] = r * l0, cyl.p[3] = r * l0 * map_.sx;
            cyl.loc = n.loc;
            g_.push(g_.add(std::move(cyl)));
            return;
        }
        circle_chords(r, tol_, edge);
        push_prism(n, std::move(edges));
    }
};

}  // namespace

void sweep_subtree(ModuleCall& c, std::uint32_t id, const SweepMap& map) { Sweeper(c, map).build(id, Map2(1.0)); }

}  // namespace kerf::eval

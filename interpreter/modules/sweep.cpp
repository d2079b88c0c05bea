#include "interpreter/modules/sweep.hpp"

#include <cmath>

#include "interpreter/modules/plane_rebuild.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;

class Sweeper {
public:
    Sweeper(ModuleCall& c, const SweepMap& map) : g_(c.graph()), map_(map), tol_(c.curve_tolerance()) {}

    void build(std::uint32_t id) {
        rebuild_subtree(g_, id, Map2(1.0), [this](const graph::Node& n, const Map2& a) { leaf(n, a); });
    }

private:
    GraphBuilder& g_;
    SweepMap map_;
    double tol_;

    void push_prism(const graph::Node& n, std::vector<glm::dvec4> edges) {
        if (edges.empty()) return;
        g_.graph.polygons.push_back(bounded_polygon(std::move(edges)));
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
        MappedEdges edge{a, {}};
        if (add_outline(g_.graph, n, edge)) return push_prism(n, std::move(edge.edges));
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
        push_prism(n, std::move(edge.edges));
    }
};

}  // namespace

void sweep_subtree(ModuleCall& c, std::uint32_t id, const SweepMap& map) { Sweeper(c, map).build(id); }

}  // namespace kerf::eval

#include "interpreter/modules/facets.hpp"

#include <cmath>

#include "interpreter/degrees.hpp"

namespace kerf::eval {

int honoured_facets(const ModuleCall& c) {
    const double fn = c.args.fn;
    return fn >= 3 && fn <= 12 && fn == std::floor(fn) ? static_cast<int>(fn) : 0;
}

void add_regular_prism(ModuleCall& c, int n, double r, double taper) {
    csg::Polygon2 poly;
    poly.lo = glm::dvec2(r), poly.hi = glm::dvec2(-r);
    auto vertex = [&](int i) {
        const double a = 360.0 * (i % n) / n;
        return glm::dvec2(r * cos_deg(a), r * sin_deg(a));
    };
    for (int i = 0; i < n; ++i) {
        const glm::dvec2 p = vertex(i), q = vertex(i + 1);
        poly.edges.emplace_back(p.x, p.y, q.x, q.y);
        poly.lo = glm::min(poly.lo, p), poly.hi = glm::max(poly.hi, p);
    }
    auto& polys = c.graph().graph.polygons;
    polys.push_back(std::move(poly));
    c.add_primitive(csg::PrimKind::Prism, {0, 1, taper}, static_cast<std::uint32_t>(polys.size() - 1));
    c.graph().graph.nodes[c.graph().pending.back()].flat = true;
}

}  // namespace kerf::eval

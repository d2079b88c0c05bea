#include "interpreter/modules/facets.hpp"

#include <cmath>

#include "interpreter/degrees.hpp"

namespace kerf::eval {

namespace {
// OpenSCAD's vertex i of n on the circle of radius r (generate_circle).
glm::dvec2 circle_vertex(int i, int n, double r) {
    const double a = 360.0 * (i % n) / n;
    return {r * cos_deg(a), r * sin_deg(a)};
}
}  // namespace

int openscad_fragments(const ModuleCall& c, double r, const FacetVars& f) {
    constexpr double grid_fine = 0.00000095367431640625;  // OpenSCAD's GRID_FINE, 2^-20
    if (r < grid_fine || !std::isfinite(f.fn)) return 3;
    const double n = f.fn > 0 ? std::max(f.fn, 3.0) : std::ceil(std::max(std::min(360.0 / f.fa, r * 2 * M_PI / f.fs), 5.0));
    // A sphere has n·(n+1)/2 vertices: the list limit bounds what is built.
    const double limit = std::min<double>(double(c.limits().list_elements), 1e7);
    if (!(n <= limit))
        throw SourceError(c.st.loc, std::string(c.args.callee) + ": $fn = " + format_number(f.fn) + ", $fa = " + format_number(f.fa) + ", $fs = " +
                              format_number(f.fs) + " ask for " + format_number(n) + " fragments (the limit is " +
                              format_number(limit) + ", --max-list)");
    return static_cast<int>(n);
}

int honoured_facets(const ModuleCall& c, double r) {
    switch (c.facet_mode()) {
    case FacetMode::Exact: return 0;
    case FacetMode::OpenScad: return openscad_fragments(c, r, c.facet_vars());
    case FacetMode::Auto: break;
    }
    const double fn = c.args.fn;
    return fn >= 3 && fn <= 12 && fn == std::floor(fn) ? static_cast<int>(fn) : 0;
}

void add_regular_prism(ModuleCall& c, int n, double r, double taper) {
    csg::Polygon2 poly;
    poly.lo = glm::dvec2(r), poly.hi = glm::dvec2(-r);
    for (int i = 0; i < n; ++i) {
        const glm::dvec2 p = circle_vertex(i, n, r), q = circle_vertex(i + 1, n, r);
        poly.edges.emplace_back(p.x, p.y, q.x, q.y);
        poly.lo = glm::min(poly.lo, p), poly.hi = glm::max(poly.hi, p);
    }
    auto& polys = c.graph().graph.polygons;
    polys.push_back(std::move(poly));
    c.add_primitive(csg::PrimKind::Prism, {0, 1, taper}, static_cast<std::uint32_t>(polys.size() - 1));
    c.graph().graph.nodes[c.graph().pending.back()].flat = true;
}

void add_openscad_sphere(ModuleCall& c, int n, double r) {
    const int rings = (n + 1) / 2;
    graph::PolygonMesh mesh;
    mesh.points.reserve(std::size_t(rings) * std::size_t(n));
    for (int i = 0; i < rings; ++i) {
        const double phi = 180.0 * (i + 0.5) / rings;
        const double z = r * cos_deg(phi), ring = r * sin_deg(phi);
        for (int j = 0; j < n; ++j) mesh.points.emplace_back(circle_vertex(j, n, ring), z);
    }
    auto at = [n](int i, int j) { return static_cast<std::uint32_t>(i * n + j % n); };
    // Faces clockwise seen from outside (PolygonMesh): the north cap seen
    // from above backwards, the bands from the top ring down, the south cap forwards.
    std::vector<std::uint32_t> north, south;
    for (int j = n - 1; j >= 0; --j) north.push_back(at(0, j));
    for (int j = 0; j < n; ++j) south.push_back(at(rings - 1, j));
    mesh.faces.push_back(std::move(north));
    for (int i = 0; i + 1 < rings; ++i)
        for (int j = 0; j < n; ++j) mesh.faces.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
    mesh.faces.push_back(std::move(south));
    c.add_primitive(csg::PrimKind::Mesh, {}, c.add_mesh(std::move(mesh)));
}

}  // namespace kerf::eval

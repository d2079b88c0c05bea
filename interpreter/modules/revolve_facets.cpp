#include "interpreter/modules/revolve_facets.hpp"

#include <cmath>

#include "interpreter/degrees.hpp"
#include "interpreter/modules/facets.hpp"
#include "interpreter/modules/plane_rebuild.hpp"
#include "interpreter/modules/region2d.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;

// The half-space {n·x <= 0} with n in the XY plane.
void push_halfspace(GraphBuilder& g, const SourceLoc& loc, double nx, double ny) {
    graph::Node h;
    h.kind = graph::NodeKind::Primitive;
    h.prim = P::Plane;
    h.p[0] = nx, h.p[1] = ny;
    h.loc = loc;
    g.push(g.add(std::move(h)));
}

// The largest |x| of the profile's region, as OpenSCAD measures it (on the
// polygon after the 2D booleans).
double profile_radius(ModuleCall& c, const std::vector<std::uint32_t>& shapes) {
    const Region2 region = flatten_region(c.graph().graph, shapes, 0, c.curve_tolerance(), c.st.loc);
    double r = 0;
    for (const auto& path : region.paths)
        for (const auto& p : path) r = std::max(r, std::abs(region.point(p).x));
    return r;
}

// A flat copy of each shape with its transforms applied (mirrored in x
// when the profile lies at x <= 0), pushed on the pending stack: polygon
// leaves, a circle left exact (offset's corner discs) as chords within the
// curve tolerance.
void push_profile(ModuleCall& c, const std::vector<std::uint32_t>& shapes, bool mirrored) {
    GraphBuilder& g = c.graph();
    Map2 start(1.0);
    if (mirrored) start[0][0] = -1;
    for (std::uint32_t id : shapes)
        rebuild_subtree(g, id, start, [&](const graph::Node& n, const Map2& a) {
            if (++c.state().primitives > c.limits().primitives)
                throw RunLimitError(c.st.loc, "primitive limit " + std::to_string(c.limits().primitives) + " exceeded");
            MappedEdges edge{a, {}};
            if (!add_outline(g.graph, n, edge)) {
                if (n.prim != P::Cylinder) throw SourceError(n.loc, "rotate_extrude: this shape cannot be revolved");
                circle_chords(n.p[2], c.curve_tolerance(), edge);
            }
            g.graph.polygons.push_back(bounded_polygon(std::move(edge.edges)));
            graph::Node leaf;
            leaf.kind = graph::NodeKind::Primitive;
            leaf.prim = P::Prism;
            leaf.index = static_cast<std::uint32_t>(g.graph.polygons.size() - 1);
            leaf.p[0] = 0, leaf.p[1] = 1;
            leaf.flat = true;
            leaf.loc = n.loc;
            g.push(g.add(std::move(leaf)));
        });
}

}  // namespace

void cut_wedge(GraphBuilder& g, std::size_t mark, double from, double angle, const SourceLoc& loc) {
    const double a1 = from + angle;
    const double sign = angle > 0 ? 1 : -1;  // counter-clockwise, or clockwise for a negative angle
    const std::size_t wedge = g.mark();
    // Left of the start ray (counter-clockwise) and right of the end ray:
    // below 180° the overlap of the two half-spaces, above it their union.
    push_halfspace(g, loc, sign * sin_deg(from), -sign * cos_deg(from));
    push_halfspace(g, loc, -sign * sin_deg(a1), sign * cos_deg(a1));
    if (std::abs(angle) > 180) g.make_node(wedge, graph::NodeKind::Union, loc);
    g.make_node(mark, graph::NodeKind::Intersection, loc);
}

bool faceted_revolve(ModuleCall& c, const std::vector<std::uint32_t>& shapes, double angle, bool mirrored,
                     double radius) {
    const bool full = std::abs(angle) >= 360;
    const double sweep = full ? 360 : angle;
    const int frags = openscad_fragments(c, radius, c.facet_vars());
    const int n = static_cast<int>(std::max(frags * std::abs(sweep) / 360, 1.0));
    const double step = sweep / n;
    if (!(radius > 0)) return false;
    if (std::abs(step) >= 180) {
        c.warn("a step of " + format_number(std::abs(step)) + "° (" + std::to_string(n) +
               (n == 1 ? " fragment" : " fragments") + ") cannot be faceted: OpenSCAD's faces would fold over; the solid is revolved exactly");
        return false;
    }
    // OpenSCAD's first meridian: −x for a full turn (its legacy start), +x
    // for a partial one; the other side for a profile at x <= 0.
    const double start = (full ? 180.0 : 0.0) + (mirrored ? 180.0 : 0.0);
    const double half = std::abs(step) / 2;
    // Each piece spans at most radius·sin(half) across its bisector.
    const double width = radius * sin_deg(half) * 1.01;
    GraphBuilder& g = c.graph();
    const std::size_t all = g.mark();
    for (int j = 0; j < n; ++j) {
        const double from = start + j * step, mid = from + step / 2;
        const glm::dvec3 u(cos_deg(mid), sin_deg(mid), 0), w(sin_deg(mid), -cos_deg(mid), 0);  // w = u × z
        const std::size_t mark = g.mark();
        push_profile(c, shapes, mirrored);
        // The profile's plane (x along u shrunk by cos(half), y up), its unit
        // slab across the wedge.
        glm::dmat4 m(1.0);
        m[0] = glm::dvec4(cos_deg(half) * u, 0);
        m[1] = glm::dvec4(0, 0, 1, 0);
        m[2] = glm::dvec4(2 * width * w, 0);
        m[3] = glm::dvec4(-width * w, 1);
        g.extrude(mark, m, c.st.loc);
        cut_wedge(g, mark, from, step, c.st.loc);
    }
    g.group(all, c.st.loc);
    return true;
}

void faceted_torus(ModuleCall& c, double R, double r) {
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    add_regular_prism(c, honoured_facets(c, r), r);
    glm::dmat4 m(1.0);
    m[3][0] = R;
    g.add_matrix(m);
    g.make_node(mark, graph::NodeKind::Transform, c.st.loc, static_cast<std::uint32_t>(g.graph.matrices.size() - 1));
    const std::vector<std::uint32_t> profile{g.pending.back()};
    g.pending.resize(mark);
    faceted_revolve(c, profile, 360, false, profile_radius(c, profile));
}

}  // namespace kerf::eval

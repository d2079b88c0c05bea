// rotate_extrude (docs/spec.md §10): the children's 2D shape, in the plane
// x = radius, y = height, revolved about Z. A revolution does not commute
// with 2D transforms (unlike linear_extrude's map of z alone), but it does
// with the 2D booleans — a point is in revolve(A ∪ B) exactly when its
// (ρ, z) is in A ∪ B — so the subtree is rebuilt with every transform
// applied to its leaves: a polygon or square becomes a Lathe leaf over its
// mapped edges, a circle a Torus (an ellipse with axes along x and y a
// torus scaled in z) and the booleans stay booleans (docs/lowering.md,
// "Revolutions"). Only the half-plane x >= 0 of each leaf is revolved
// (revolve(A) = revolve(A ∩ {x >= 0}) by that definition), so a piece that
// crosses the axis before a boolean removes that part revolves as OpenSCAD
// revolves the result, which is what OpenSCAD checks for the x sign. A
// hull, a Minkowski sum or a resize is done in the plane first, as for a
// twisted linear_extrude. A partial angle intersects the result with the
// wedge of two half-spaces through the Z axis.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "interpreter/degrees.hpp"
#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"
#include "interpreter/modules/plane_rebuild.hpp"
#include "interpreter/modules/region2d.hpp"
#include "interpreter/modules/revolve_facets.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;

// The even-odd edge set `edges` cut to its part at x >= 0: every edge
// clipped (kept in its direction), and the points where edges cross the
// axis joined in pairs, in order of height, by segments on x = 0. Each
// closed loop crosses the axis an even number of times, so the set stays
// closed; its region at x > 0, all a revolution sees, is the original's.
std::vector<glm::dvec4> clip_to_half_plane(std::vector<glm::dvec4> edges) {
    if (std::none_of(edges.begin(), edges.end(), [](const glm::dvec4& e) { return e.x < 0 || e.z < 0; })) return edges;
    std::vector<glm::dvec4> out;
    std::vector<double> axis;  // heights where an edge crosses x = 0
    for (const glm::dvec4& e : edges) {
        const bool in0 = e.x >= 0, in1 = e.z >= 0;
        if (in0 && in1) out.push_back(e);
        if (in0 == in1) continue;
        // From the end inside, exact when it lies on the axis.
        const glm::dvec2 in = in0 ? glm::dvec2(e.x, e.y) : glm::dvec2(e.z, e.w);
        const glm::dvec2 away = in0 ? glm::dvec2(e.z, e.w) : glm::dvec2(e.x, e.y);
        const double y = in.x == 0 ? in.y : in.y + (away.y - in.y) * (in.x / (in.x - away.x));
        axis.push_back(y);
        if (in.x == 0) continue;
        out.push_back(in0 ? glm::dvec4(in.x, in.y, 0, y) : glm::dvec4(0, y, in.x, in.y));
    }
    std::sort(axis.begin(), axis.end());
    for (std::size_t i = 0; i + 1 < axis.size(); i += 2)
        if (axis[i] != axis[i + 1]) out.emplace_back(0, axis[i], 0, axis[i + 1]);
    return out;
}

class Revolver {
public:
    Revolver(ModuleCall& c, double tolerance) : c_(c), g_(c.graph()), tol_(tolerance) {}

    // The revolved copy of node `id` pushed on the builder's pending stack.
    void build(std::uint32_t id) {
        rebuild_subtree(g_, id, Map2(1.0), [this](const graph::Node& n, const Map2& a) { leaf(n, a); });
    }

    bool mirrored = false;  // the shape lies at x <= 0: revolve its mirror image

private:
    ModuleCall& c_;
    GraphBuilder& g_;
    double tol_;

    // An operand that is empty (a piece wholly at x < 0): kept in place, as
    // it may be the minuend or a factor of an intersection.
    void push_empty(const graph::Node& n) { g_.make_node(g_.mark(), graph::NodeKind::Union, n.loc); }

    void push_polygon(const graph::Node& n, std::vector<glm::dvec4> edges) {
        if (mirrored)
            for (glm::dvec4& e : edges) e.x = -e.x, e.z = -e.z;
        edges = clip_to_half_plane(std::move(edges));
        if (edges.empty()) return push_empty(n);
        for (glm::dvec4& e : edges) e.x = std::max(e.x, 0.0), e.z = std::max(e.z, 0.0);  // -0
        g_.graph.polygons.push_back(bounded_polygon(std::move(edges)));
        graph::Node leaf;
        leaf.kind = graph::NodeKind::Primitive;
        leaf.prim = P::Lathe;
        leaf.index = static_cast<std::uint32_t>(g_.graph.polygons.size() - 1);
        leaf.loc = n.loc;
        g_.push(g_.add(std::move(leaf)));
    }

    void leaf(const graph::Node& n, const Map2& a) {
        MappedEdges edge{a, {}};
        if (add_outline(g_.graph, n, edge)) return push_polygon(n, std::move(edge.edges));
        // A circle of radius r: its image is an ellipse. With axes along x
        // and y (the rows of L orthogonal) and clear of the axis, a torus
        // scaled by (ex, ex, ez); otherwise (tilted, or touching the axis:
        // the torus leaf needs R > r) a polygon whose chords stay within the
        // curve tolerance of it.
        const double r = n.p[2];
        const glm::dvec2 row0(a[0][0], a[1][0]), row1(a[0][1], a[1][1]);
        const glm::dvec2 c = apply(a, {0, 0});
        const double ex = r * glm::length(row0), ez = r * glm::length(row1);
        const double cx = mirrored ? -c.x : c.x;
        if (cx <= -ex) return push_empty(n);  // wholly at x <= 0
        if (glm::dot(row0, row1) == 0 && cx > ex) {
            graph::Node torus;
            torus.kind = graph::NodeKind::Primitive;
            torus.prim = P::Torus;
            torus.p[0] = cx / ex, torus.p[1] = 1;
            torus.loc = n.loc;
            const std::size_t mark = g_.mark();
            g_.push(g_.add(std::move(torus)));
            glm::dmat4 m(1.0);
            m[0][0] = m[1][1] = ex, m[2][2] = ez, m[3][2] = c.y;
            g_.add_matrix(m);
            g_.make_node(mark, graph::NodeKind::Transform, n.loc, static_cast<std::uint32_t>(g_.graph.matrices.size() - 1));
            return;
        }
        circle_chords(r, tol_, edge);
        push_polygon(n, std::move(edge.edges));
    }
};

void rotate_extrude(ModuleCall& c) {
    const Args& a = c.args;
    static constexpr const char* kDxf[] = {"file", "layer", "origin", "scale"};
    for (std::size_t i = 0; i < 4; ++i) {
        if (!a.has(i)) continue;
        const std::string msg = std::string("OpenSCAD's deprecated ") + kDxf[i] +
                                " argument (DXF import) is not supported; give the profile as 2D children (angle = ...)";
        // OpenSCAD warns that it cannot open the file and revolves the children.
        if (!c.lenient()) arg_error(a, msg);
        c.warn(msg + " (ignored)");
    }
    const double angle = arg_number(a, 5, "angle", 360);
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    {
        GhostFrameScope hide(c.state(), "rotate_extrude");
        c.children();
    }
    const std::vector<std::uint32_t> shapes = c.flat_children(mark, "revolves");
    if (shapes.empty() || angle == 0) return;  // angle 0: the empty solid, as in OpenSCAD
    // OpenSCAD checks the sign of x on the 2D result, after the booleans
    // (a piece may cross the axis where a difference removes it): so does
    // kerf, on the same region flattened within the curve tolerance.
    const Region2 region = flatten_region(g.graph, shapes, 0, c.curve_tolerance(), c.st.loc);
    if (region.paths.empty()) return;  // no area: the empty solid
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;
    for (const ClipperLib::Path& path : region.paths)
        for (const ClipperLib::IntPoint& p : path) {
            const double x = region.point(p).x;
            xmin = std::min(xmin, x), xmax = std::max(xmax, x);
        }
    if (xmin < 0 && xmax > 0) {
        char range[96];
        std::snprintf(range, sizeof range, "%.2f -> %.2f", xmin, xmax);
        const std::string msg =
            std::string("all points for rotate_extrude() must have the same X coordinate sign (range is ") + range + ")";
        // OpenSCAD 2021.01 prints it as an ERROR, makes nothing of this
        // rotate_extrude and goes on (exit 0 when something else remains).
        if (!c.lenient()) throw SourceError(c.st.loc, "rotate_extrude: " + msg);
        c.warn(msg + " (nothing is made)");
        return;
    }
    Revolver rev(c, c.curve_tolerance());
    rev.mirrored = xmax <= 0 && xmin < 0;
    const double radius = std::max(std::abs(xmin), std::abs(xmax));  // OpenSCAD's fragment radius
    if (c.facet_mode() != FacetMode::OpenScad) c.exact_curve();  // revolved exactly, not in $fn steps
    else if (faceted_revolve(c, shapes, angle, rev.mirrored, radius)) return;
    for (std::uint32_t id : shapes) rev.build(id);
    g.group(mark, c.st.loc);
    // OpenSCAD sweeps from the side the profile lies on: +x, or −x when mirrored.
    if (std::abs(angle) < 360) cut_wedge(g, mark, rev.mirrored ? 180 : 0, angle, c.st.loc);
}

const ModuleEntry kRevolve[] = {
    {"rotate_extrude", ModuleKind::Operation, {"file", "layer", "origin", "scale", "convexity", "angle"}, rotate_extrude},
};

}  // namespace

std::span<const ModuleEntry> revolve_modules() { return kRevolve; }

}  // namespace kerf::eval

// rotate_extrude (docs/spec.md §10): the children's 2D shape, in the plane
// x = radius, y = height, revolved about Z. A revolution does not commute
// with 2D transforms (unlike linear_extrude's map of z alone), but it does
// with the 2D booleans — a point is in revolve(A ∪ B) exactly when its
// (ρ, z) is in A ∪ B — so the subtree is rebuilt with every transform
// applied to its leaves: a polygon or square becomes a Lathe leaf over its
// mapped edges, a circle a Torus (an ellipse with axes along x and y a
// torus scaled in z) and the booleans stay booleans (docs/lowering.md,
// "Revolutions"). A partial angle intersects the result with the wedge of
// two half-spaces through the Z axis.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "interpreter/degrees.hpp"
#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"
#include "interpreter/modules/plane_rebuild.hpp"
#include "interpreter/modules/revolve_facets.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;

class Revolver {
public:
    Revolver(ModuleCall& c, double tolerance) : c_(c), g_(c.graph()), tol_(tolerance) {}

    // The x range every leaf's points span, for the sign check.
    double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin;

    // First pass: each leaf's 2D points mapped, to learn the x range (the
    // sign decides the mirror before anything is built).
    void measure(std::uint32_t id, const Map2& a) {
        const graph::Node& n = g_.graph.nodes[id];
        if (n.kind == graph::NodeKind::Primitive) {
            for (const glm::dvec2 p : outline(n, a)) extend(p.x);
            return;
        }
        // Lowering builds these from their children's points and boxes,
        // which a revolution does not carry over (a revolved hull is no hull).
        if (n.kind == graph::NodeKind::Hull || n.kind == graph::NodeKind::Minkowski || n.kind == graph::NodeKind::Resize)
            throw SourceError(n.loc, "rotate_extrude: hull(), minkowski() and resize() of 2D shapes cannot be revolved yet");
        const Map2 inner = n.kind == graph::NodeKind::Transform ? a * plane_part(g_.graph.matrices[n.index]) : a;
        for (std::uint32_t k = 0; k < n.child_count; ++k) measure(g_.graph.child_refs[n.first_child + k], inner);
    }

    // Second pass: the revolved copy of node `id` pushed on the builder's pending stack.
    void build(std::uint32_t id) {
        rebuild_subtree(g_, id, Map2(1.0), [this](const graph::Node& n, const Map2& a) { leaf(n, a); });
    }

    bool mirrored = false;  // the shape lies at x <= 0: revolve its mirror image

private:
    ModuleCall& c_;
    GraphBuilder& g_;
    double tol_;

    void extend(double x) { xmin = std::min(xmin, x), xmax = std::max(xmax, x); }

    // A leaf's mapped boundary points: the polygon's vertices, or for a
    // circle the extreme points of its image along x.
    std::vector<glm::dvec2> outline(const graph::Node& n, const Map2& a) const {
        std::vector<glm::dvec2> out;
        if (n.prim == P::Box) {
            for (glm::dvec2 p : {glm::dvec2(n.p[0], n.p[1]), glm::dvec2(n.p[3], n.p[1]), glm::dvec2(n.p[3], n.p[4]),
                                 glm::dvec2(n.p[0], n.p[4])})
                out.push_back(apply(a, p));
        } else if (n.prim == P::Prism) {
            for (const glm::dvec4& e : g_.graph.polygons[n.index].edges) out.push_back(apply(a, {e.x, e.y}));
        } else if (n.prim == P::Cylinder) {
            const glm::dvec2 c = apply(a, {0, 0});
            const double ex = n.p[2] * std::hypot(a[0][0], a[1][0]);  // half the image's width
            out = {{c.x - ex, c.y}, {c.x + ex, c.y}};
        } else {
            throw SourceError(n.loc, "rotate_extrude: this shape cannot be revolved");
        }
        return out;
    }

    void push_polygon(const graph::Node& n, std::vector<glm::dvec4> edges) {
        for (glm::dvec4& e : edges) {
            if (mirrored) e.x = -e.x, e.z = -e.z;
            e.x = std::max(e.x, 0.0), e.z = std::max(e.z, 0.0);  // -0 and a circle's rounded rim
        }
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
        const double cx = std::abs(c.x);
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
    c.children();
    const std::vector<std::uint32_t> shapes = c.flat_children(mark, "revolves");
    if (shapes.empty() || angle == 0) return;  // angle 0: the empty solid, as in OpenSCAD
    Revolver rev(c, c.curve_tolerance());
    for (std::uint32_t id : shapes) rev.measure(id, Map2(1.0));
    if (rev.xmin < 0 && rev.xmax > 0) {
        char range[96];
        std::snprintf(range, sizeof range, "%.2f -> %.2f", rev.xmin, rev.xmax);
        // An error in both dialects (not the .scad warning of arg_error):
        // OpenSCAD reports it as an ERROR and exits 1 too.
        throw SourceError(c.st.loc, std::string("rotate_extrude: all points must have the same x coordinate sign (range is ") +
                                        range + ")");
    }
    rev.mirrored = rev.xmax <= 0 && rev.xmin < 0;
    if (c.facet_mode() != FacetMode::OpenScad) c.exact_curve();  // revolved exactly, not in $fn steps
    else if (faceted_revolve(c, shapes, angle, rev.mirrored)) return;
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

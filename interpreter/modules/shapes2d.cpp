// 2D shapes and linear_extrude (docs/spec.md §10). A 2D shape is carried in
// the graph as its extrusion over the unit slab 0 < z < 1, flagged flat
// (scene_graph.hpp): square a Box, circle a Cylinder, polygon a Prism over
// its even-odd edge set. An extrusion is then a map of z alone, so 2D
// booleans and transforms become the 3D ones of the extruded pieces
// (docs/lowering.md, "2D shapes").
#include <cmath>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/facets.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;

void mark_flat(ModuleCall& c) { c.graph().graph.nodes[c.graph().pending.back()].flat = true; }

void square(ModuleCall& c) {
    const Args& a = c.args;
    glm::dvec2 size(1);
    if (a.has(0) && a[0].is_number()) {
        size = glm::dvec2(arg_number(a, 0, "size", 1));
    } else if (a.has(0)) {
        if (!a[0].is_vector(2)) arg_error(a, "size must be a number or a vector of 2 numbers, got " + to_repr(a[0]));
        size = {a[0].as_list()[0].as_number(), a[0].as_list()[1].as_number()};
    }
    for (int k = 0; k < 2; ++k)
        if (!(size[k] > 0) || !std::isfinite(size[k]))
            arg_error(a, "size must be positive and finite, got " + format_number(size[k]));
    const bool center = arg_bool(a, 1, "center", false);
    const glm::dvec2 lo = center ? -size / 2.0 : glm::dvec2(0), hi = center ? size / 2.0 : size;
    c.add_primitive(P::Box, {lo.x, lo.y, 0, hi.x, hi.y, 1});
    mark_flat(c);
}

void circle(ModuleCall& c) {
    const Args& a = c.args;
    if (a.has(0) && a.has(1)) arg_error(a, "give r or d, not both");
    const double r = a.has(1) ? arg_number(a, 1, "d", 2) / 2 : arg_number(a, 0, "r", 1);
    if (!(r > 0)) arg_error(a, "radius must be positive, got " + format_number(r));
    if (const int n = honoured_facets(c)) return add_regular_prism(c, n, r);
    c.add_primitive(P::Cylinder, {0, 1, r, r});
    mark_flat(c);
}

// OpenSCAD's polygon(points, paths): without paths one closed path through
// all points in order; with paths, each a closed path of point indices.
// The edges of all paths together are filled by the even-odd rule.
void polygon(ModuleCall& c) {
    const Args& a = c.args;
    if (!a.has(0) || !a[0].is_list()) arg_error(a, "points must be a list of [x, y] points");
    std::vector<glm::dvec2> pts;
    for (const Value& p : a[0].as_list()) {
        if (!p.is_vector(2)) arg_error(a, "points must be a list of [x, y] points, got an element " + to_repr(p));
        const glm::dvec2 q(p.as_list()[0].as_number(), p.as_list()[1].as_number());
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) arg_error(a, "points must be finite, got " + to_repr(p));
        pts.push_back(q);
    }
    std::vector<std::vector<std::uint32_t>> paths;
    if (a.has(1) && !a[1].is_undef()) {
        if (!a[1].is_list()) arg_error(a, "paths must be a list of point index lists, got " + to_repr(a[1]));
        std::size_t pi = 0;
        for (const Value& path : a[1].as_list()) {
            if (!path.is_vector())
                arg_error(a, "path " + std::to_string(pi) + " must be a list of point indices, got " + to_repr(path));
            std::vector<std::uint32_t> idx;
            for (const Value& v : path.as_list()) {
                const double d = v.as_number();
                if (d != std::floor(d) || d < 0 || d >= static_cast<double>(pts.size()))
                    arg_error(a, "path " + std::to_string(pi) + " refers to point " + format_number(d) +
                                     " (there are " + std::to_string(pts.size()) + " points)");
                idx.push_back(static_cast<std::uint32_t>(d));
            }
            paths.push_back(std::move(idx));
            ++pi;
        }
    } else {
        paths.emplace_back();
        for (std::uint32_t i = 0; i < pts.size(); ++i) paths.back().push_back(i);
    }
    csg::Polygon2 poly;
    poly.lo = glm::dvec2(std::numeric_limits<double>::infinity());
    poly.hi = -poly.lo;
    for (const auto& path : paths)
        for (std::size_t i = 0; i < path.size(); ++i) {
            const glm::dvec2 p = pts[path[i]], q = pts[path[(i + 1) % path.size()]];
            if (p != q) poly.edges.emplace_back(p.x, p.y, q.x, q.y);
            poly.lo = glm::min(poly.lo, p);
            poly.hi = glm::max(poly.hi, p);
        }
    if (poly.edges.empty()) return;  // no points, or all in one place: the empty shape
    auto& polys = c.graph().graph.polygons;
    polys.push_back(std::move(poly));
    c.add_primitive(P::Prism, {0, 1}, static_cast<std::uint32_t>(polys.size() - 1));
    mark_flat(c);
}

// linear_extrude(scale = s) of a 2D subtree on the unit slab: the section at
// z is (1 + (s − 1)·z) times the shape, a map that commutes with the 2D
// booleans and, through each 2D transform x -> L·x + c, becomes
// x -> L·x + c + (s − 1)·z·c (a shear in z, still affine: composing such
// maps gives the map of the composition). So every transform gets that
// shear and every leaf its tapered form: a circle a frustum, a polygon a
// tapered prism, a square a tapered prism of its four corners. Rewrites
// the subtree in place (its nodes belong to this extrusion alone).
void taper(graph::SceneGraph& g, std::uint32_t root, double s) {
    std::vector<std::uint32_t> todo{root};
    while (!todo.empty()) {
        graph::Node& n = g.nodes[todo.back()];
        todo.pop_back();
        if (n.kind == graph::NodeKind::Primitive) {
            if (n.prim == P::Cylinder) {
                n.p[3] = n.p[2] * s;
            } else if (n.prim == P::Box) {
                csg::Polygon2 poly;
                const double x0 = n.p[0], y0 = n.p[1], x1 = n.p[3], y1 = n.p[4];
                poly.edges = {{x0, y0, x1, y0}, {x1, y0, x1, y1}, {x1, y1, x0, y1}, {x0, y1, x0, y0}};
                poly.lo = {x0, y0};
                poly.hi = {x1, y1};
                g.polygons.push_back(std::move(poly));
                n.prim = P::Prism;
                n.index = static_cast<std::uint32_t>(g.polygons.size() - 1);
                n.p[0] = 0, n.p[1] = 1, n.p[2] = s - 1;
                n.p[3] = n.p[4] = n.p[5] = 0;
            } else if (n.prim == P::Prism) {
                n.p[2] = s - 1;
            }
            continue;
        }
        // The taper commutes with a hull (the hull of the tapered pieces is
        // the tapered hull: both are the hull of the bottom and the scaled
        // top sections), not with a Minkowski sum or a resize's box.
        if (n.kind == graph::NodeKind::Minkowski || n.kind == graph::NodeKind::Resize)
            throw SourceError(n.loc, "linear_extrude: scale is not implemented yet for minkowski() and resize() of 2D shapes");
        if (n.kind == graph::NodeKind::Transform) {
            glm::dmat4& m = g.matrices[n.index];
            m[2][0] = (s - 1) * m[3][0];
            m[2][1] = (s - 1) * m[3][1];
        }
        for (std::uint32_t k = 0; k < n.child_count; ++k) todo.push_back(g.child_refs[n.first_child + k]);
    }
}

void linear_extrude(ModuleCall& c) {
    const Args& a = c.args;
    const double h = arg_positive(a, 0, "height", 100);
    const bool center = arg_bool(a, 1, "center", false);
    if (arg_number(a, 3, "twist", 0) != 0) arg_unsupported(a, "twist is not implemented yet (only twist = 0)");
    if (a.has(4)) arg_positive(a, 4, "slices", 1);  // accepted: kerf extrudes exactly, not in slices
    double top = 1;  // the top section's scale
    if (a.has(5)) {
        const Value& s = a[5];
        if (!s.is_number() && !s.is_vector(2)) arg_error(a, "scale must be a number or [sx, sy], got " + to_repr(s));
        top = s.is_number() ? s.as_number() : s.as_list()[0].as_number();
        if (s.is_vector(2) && s.as_list()[1].as_number() != top)
            arg_unsupported(a, "a scale that differs in x and y is not implemented yet, got " + to_repr(s));
        if (!std::isfinite(top) || top < 0) arg_error(a, "scale must be a finite number >= 0, got " + to_repr(s));
        if (top == 0) arg_unsupported(a, "scale = 0 (a pointed top) is not implemented yet");
    }
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    c.children();
    if (g.mark() == mark) return;
    for (std::size_t i = mark; i < g.pending.size(); ++i)
        if (!g.graph.nodes[g.pending[i]].flat)
            throw SourceError(g.graph.nodes[g.pending[i]].loc, "linear_extrude: extrudes 2D shapes, not 3D solids");
    if (top != 1)
        for (std::size_t i = mark; i < g.pending.size(); ++i) taper(g.graph, g.pending[i], top);
    const double z0 = center ? -h / 2 : 0;
    g.extrude(mark, z0, z0 + h, c.st.loc);
}

const ModuleEntry kShapes2d[] = {
    {"square", ModuleKind::Solid, {"size", "center"}, square},
    {"circle", ModuleKind::Solid, {"r", "d"}, circle},
    {"polygon", ModuleKind::Solid, {"points", "paths", "convexity"}, polygon},
    {"linear_extrude", ModuleKind::Operation, {"height", "center", "convexity", "twist", "slices", "scale"}, linear_extrude},
};

}  // namespace

std::span<const ModuleEntry> shape2d_modules() { return kShapes2d; }

}  // namespace kerf::eval

// 2D shapes and linear_extrude (docs/spec.md §10). A 2D shape is carried in
// the graph as its extrusion over the unit slab 0 < z < 1, flagged flat
// (scene_graph.hpp): square a Box, circle a Cylinder, polygon a Prism over
// its even-odd edge set. An extrusion is then a map of z alone, so 2D
// booleans and transforms become the 3D ones of the extruded pieces
// (docs/lowering.md, "2D shapes").
#include <cmath>
#include <numbers>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/facets.hpp"
#include "interpreter/modules/module_call.hpp"
#include "interpreter/modules/sweep.hpp"
#include "interpreter/modules/twist_slices.hpp"

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
    if (const int n = honoured_facets(c, r)) return add_regular_prism(c, n, r);
    c.exact_curve();
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
void taper(GraphBuilder& b, std::uint32_t root, double s) {
    graph::SceneGraph& g = b.graph;
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
        // top sections), not with a Minkowski sum or a resize's box: those
        // are swept instead (linear_extrude below).
        if (n.kind == graph::NodeKind::Transform) {
            glm::dmat4 m = g.matrices[n.index];
            m[2][0] = (s - 1) * m[3][0];
            m[2][1] = (s - 1) * m[3][1];
            b.set_matrix(n.index, m);
        }
        for (std::uint32_t k = 0; k < n.child_count; ++k) todo.push_back(g.child_refs[n.first_child + k]);
    }
}

// True when the 2D subtree at `id` holds a minkowski() or resize(), which
// a taper does not commute with.
bool has_sum_or_resize(const graph::SceneGraph& g, std::uint32_t id) {
    const graph::Node& n = g.nodes[id];
    if (n.kind == graph::NodeKind::Minkowski || n.kind == graph::NodeKind::Resize) return true;
    for (std::uint32_t k = 0; k < n.child_count; ++k)
        if (has_sum_or_resize(g, g.child_refs[n.first_child + k])) return true;
    return false;
}

// A scale argument: a number or [sx, sy], each finite and >= 0.
glm::dvec2 scale_arg(const Args& a, std::size_t i) {
    if (!a.has(i)) return glm::dvec2(1);
    const Value& s = a[i];
    if (!s.is_number() && !s.is_vector(2)) arg_error(a, "scale must be a number or [sx, sy], got " + to_repr(s));
    const glm::dvec2 k = s.is_number() ? glm::dvec2(s.as_number())
                                       : glm::dvec2(s.as_list()[0].as_number(), s.as_list()[1].as_number());
    for (int j = 0; j < 2; ++j)
        if (!std::isfinite(k[j]) || k[j] < 0) arg_error(a, "scale must be finite numbers >= 0, got " + to_repr(s));
    return k;
}

// linear_extrude(height, center, convexity, twist, slices, scale, v): the
// section at τ = z/h is scale(τ)·rotate(−twist·τ)·shape (docs/spec.md §10).
// A uniform scale without twist keeps the subtree (taper) unless it holds a
// minkowski() or resize(); anything else rebuilds it with the transforms
// applied (sweep.hpp). `v` tilts the slab:
// the section at τ moves by τ·h·v/|v| (the map of the unit slab, a shear).
void linear_extrude(ModuleCall& c) {
    const Args& a = c.args;
    glm::dvec3 dir(0, 0, 1);
    if (a.has(6)) {
        if (!a[6].is_vector(3)) arg_error(a, "v must be a vector of 3 numbers, got " + to_repr(a[6]));
        const auto& l = a[6].as_list();
        dir = {l[0].as_number(), l[1].as_number(), l[2].as_number()};
        if (!std::isfinite(dir.x) || !std::isfinite(dir.y) || !std::isfinite(dir.z) || !(dir.z > 0))
            arg_error(a, "v must be finite and point upwards (v.z > 0), got " + to_repr(a[6]));
    }
    const double vlen = glm::length(dir);
    const double h = a.has(0) || !a.has(6) ? arg_positive(a, 0, "height", 100) : vlen;
    const bool center = arg_bool(a, 1, "center", false);
    const double twist = arg_number(a, 3, "twist", 0);
    // slices only cut a twisted or unevenly scaled side (straight sides are
    // flat however many slices OpenSCAD makes), and kerf sweeps those
    // exactly unless --facets openscad asks for OpenSCAD's cut. OpenSCAD
    // counts its own slices for any number below 1; .sdl wants a positive one.
    const double slices = !a.has(4) ? 0 : c.lenient() ? arg_number(a, 4, "slices", 0) : arg_positive(a, 4, "slices", 1);
    const glm::dvec2 top = scale_arg(a, 5);  // the top section's scales
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    {
        GhostFrameScope hide(c.state(), "linear_extrude");
        c.children();
    }
    if (g.mark() == mark) return;
    for (std::size_t i = mark; i < g.pending.size(); ++i) {
        if (g.graph.nodes[g.pending[i]].flat) continue;
        if (!c.lenient())
            throw SourceError(g.graph.nodes[g.pending[i]].loc, "linear_extrude: extrudes 2D shapes, not 3D solids");
        c.warn("Ignoring 3D child object for 2D operation");  // OpenSCAD drops it
        g.pending.erase(g.pending.begin() + std::ptrdiff_t(i--));
    }
    if (g.mark() == mark) return;
    bool sweep = twist != 0 || top.x != top.y;
    // OpenSCAD cuts these sides into slices of flat triangles: under
    // --facets openscad so does kerf (twist_slices.hpp); otherwise it sweeps them exactly.
    const bool sliced = sweep && c.facet_mode() == FacetMode::OpenScad;
    if (sweep && !sliced && slices > 0)
        c.warn("slices = " + format_number(slices) + " is ignored: kerf sweeps the twisted or unevenly scaled sides exactly");
    else if (sweep && !sliced)
        c.exact_curve();  // OpenSCAD takes its slices from $fn, $fa and $fs here
    for (std::size_t i = mark; i < g.pending.size() && top.x != 1; ++i)
        sweep = sweep || has_sum_or_resize(g.graph, g.pending[i]);
    if (sliced) {
        const std::vector<std::uint32_t> shapes(g.pending.begin() + std::ptrdiff_t(mark), g.pending.end());
        g.pending.resize(mark);
        add_openscad_slices(c, shapes, {h, twist, top, slices});
        if (g.mark() == mark) return;
    } else if (sweep) {
        const std::vector<std::uint32_t> shapes(g.pending.begin() + std::ptrdiff_t(mark), g.pending.end());
        g.pending.resize(mark);
        for (std::uint32_t id : shapes) sweep_subtree(c, id, {top.x, top.y, twist * std::numbers::pi / 180});
        if (g.mark() == mark) return;
    } else if (top.x != 1) {
        for (std::size_t i = mark; i < g.pending.size(); ++i) taper(g, g.pending[i], top.x);
    }
    // The unit slab to its place: the top section moved by h·v/|v|.
    const glm::dvec3 up = h / vlen * dir;
    glm::dmat4 m(1.0);
    m[2] = glm::dvec4(up, 0);
    if (center) m[3] = glm::dvec4(-0.5 * up, 1);
    g.extrude(mark, m, c.st.loc);
}

const ModuleEntry kShapes2d[] = {
    {"square", ModuleKind::Solid, {"size", "center"}, square},
    {"circle", ModuleKind::Solid, {"r", "d"}, circle},
    {"polygon", ModuleKind::Solid, {"points", "paths", "convexity"}, polygon},
    {"linear_extrude", ModuleKind::Operation, {"height", "center", "convexity", "twist", "slices", "scale", "v"},
     linear_extrude},
};

}  // namespace

std::span<const ModuleEntry> shape2d_modules() { return kShapes2d; }

}  // namespace kerf::eval

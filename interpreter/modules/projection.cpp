// projection(cut = false | true) (docs/spec.md §10; docs/lowering.md,
// "Projection"): a 3D subtree to a 2D shape.
// - cut = true, the section with z = 0: a section commutes with the
//   booleans (section(A − B) = section(A) − section(B)), so the subtree is
//   rebuilt with the booleans kept and each leaf replaced by its section,
//   exact where that is a circle under an affine map (a sphere, a cylinder
//   or extruded circle cut across its axis), a polygon (a box, a mesh, a
//   straight extrusion cut at any angle: the preimage of its section
//   clipped to the slab, or along its axis rectangles; a uniformly tapered
//   extrusion of one convex path, whose triangles are exact), and otherwise the
//   section of the leaf's tessellation within the curve tolerance.
// - cut = false, the shadow: a projection commutes with unions only, so a
//   subtree of unions is the union of its leaves' shadows (a sphere's an
//   exact ellipse, a straight extrusion's its section swept along the
//   projected axis, a mesh's or box's its triangles' union, other curved
//   leaves their tessellation's); a subtree with an intersection or a
//   difference is the union of its sections at n = ⌈1/√tolerance⌉ heights
//   (100 at the default), measured in docs/accuracy.md ("Projection").
#include <algorithm>
#include <cmath>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"
#include "interpreter/modules/plane_map.hpp"
#include "interpreter/modules/projection_leaf.hpp"
#include "interpreter/modules/region2d.hpp"
#include "interpreter/modules/subgraph.hpp"

namespace kerf::eval {

namespace {

using P = csg::PrimKind;
using NK = graph::NodeKind;
using namespace projection;
using Loops = std::vector<std::vector<glm::dvec2>>;

glm::dvec2 xy(const glm::dmat4& m, glm::dvec3 p) { return glm::dvec2(m * glm::dvec4(p, 1)); }

// The plane z = 0 meets an extrusion's axis at a right angle (up to the
// rounding of a rotation's cosines).
bool across(glm::dvec3 row) { return std::abs(row.x) + std::abs(row.y) <= 1e-14 * std::abs(row.z); }

bool straight(const graph::Node& n) {
    return n.prim == P::Cylinder ? n.p[2] == n.p[3] : n.p[2] == 0 && n.p[3] == 0 && n.p[4] == 0;
}

// The polygon of a Prism leaf as its runs of edges (polygon() writes each
// path's edges in order), as region2d reads it.
Loops polygon_loops(const csg::Polygon2& poly) {
    Loops out;
    bool open = false;
    glm::dvec2 last(0);
    for (const glm::dvec4& e : poly.edges) {
        const glm::dvec2 p(e.x, e.y), q(e.z, e.w);
        if (!open || p != last) out.push_back({p});
        if (q != out.back().front()) out.back().push_back(q);
        last = q, open = true;
    }
    return out;
}

// A uniformly tapered extrusion of one convex path (a cone or frustum
// under --facets openscad) is a polyhedron: each side a flat trapezoid
// (the edge and its scaled copy), the ends fans. Its triangles are exact,
// so their section is too. Anything else: false.
bool tapered_triangles(const graph::SceneGraph& g, const graph::Node& n, const glm::dmat4& m, std::vector<Tri>& out) {
    if (n.p[3] != 0 || n.p[4] != 0) return false;
    const Loops loops = polygon_loops(g.polygons[n.index]);
    if (loops.size() != 1 || loops[0].size() < 3) return false;
    const std::vector<glm::dvec2>& l = loops[0];
    const std::size_t k = l.size();
    int sign = 0;
    for (std::size_t i = 0; i < k; ++i) {
        const glm::dvec2 a = l[(i + 1) % k] - l[i], b = l[(i + 2) % k] - l[(i + 1) % k];
        const double c = a.x * b.y - a.y * b.x;
        if (c == 0) continue;
        if (sign != 0 && (c > 0) != (sign > 0)) return false;
        sign = c > 0 ? 1 : -1;
    }
    const double top = 1 + n.p[2];
    auto at = [&](glm::dvec2 q, double scale, double z) { return glm::dvec3(m * glm::dvec4(scale * q, z, 1)); };
    for (std::size_t i = 0; i < k; ++i) {
        const glm::dvec2 a = l[i], b = l[(i + 1) % k];
        const glm::dvec3 a0 = at(a, 1, n.p[0]), b0 = at(b, 1, n.p[0]), a1 = at(a, top, n.p[1]), b1 = at(b, top, n.p[1]);
        out.push_back({a0, b0, b1});
        out.push_back({a0, b1, a1});
        if (i + 1 < k && i > 0) {
            out.push_back({at(l[0], 1, n.p[0]), at(a, 1, n.p[0]), at(b, 1, n.p[0])});
            out.push_back({at(l[0], top, n.p[1]), at(a, top, n.p[1]), at(b, top, n.p[1])});
        }
    }
    return true;
}

// The convex polygon `poly` clipped to lo < f < hi, f linear on it.
std::vector<glm::dvec2> clip_band(std::vector<glm::dvec2> poly, glm::dvec3 f, double lo, double hi) {
    auto clip = [&](double sign, double bound) {
        std::vector<glm::dvec2> out;
        auto value = [&](glm::dvec2 p) { return sign * (f.x * p.x + f.y * p.y + f.z - bound); };
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
            const double va = value(a), vb = value(b);
            if (va >= 0) out.push_back(a);
            if ((va >= 0) != (vb >= 0)) out.push_back(a + (b - a) * (va / (va - vb)));
        }
        poly = std::move(out);
    };
    clip(1, lo);
    clip(-1, hi);
    return poly;
}

class Sectioner {
public:
    Sectioner(GraphBuilder& g, double tol, const SourceLoc& loc) : g_(g), tol_(tol), loc_(loc) {}

    // The section of node `id` under m with z = 0 as a flat node, or kEmpty.
    std::uint32_t walk(std::uint32_t id, const glm::dmat4& m) {
        const graph::Node n = g_.graph.nodes[id];  // a copy: the walk adds nodes
        auto child = [&](std::uint32_t k) { return g_.graph.child_refs[n.first_child + k]; };
        switch (n.kind) {
        case NK::Primitive:
            return leaf(n, m);
        case NK::Transform:
            return walk(child(0), m * g_.graph.matrices[n.index]);
        case NK::Appearance:
            return walk(child(0), m);
        case NK::Hull:
        case NK::Minkowski:
        case NK::Resize:
            throw SourceError(n.loc, "projection(): hull(), minkowski() or resize() left unresolved");  // see projection_call
        default:
            break;
        }
        std::vector<std::uint32_t> parts;
        for (std::uint32_t k = 0; k < n.child_count; ++k) {
            const std::uint32_t s = walk(child(k), m);
            if (s == kEmpty && (n.kind == NK::Intersection || (n.kind == NK::Difference && k == 0))) return kEmpty;
            if (s != kEmpty) parts.push_back(s);
        }
        if (parts.empty()) return kEmpty;
        if (parts.size() == 1) return parts[0];
        return op_node(g_, n.kind, parts, loc_);
    }

private:
    GraphBuilder& g_;
    double tol_;
    SourceLoc loc_;

    std::uint32_t leaf(const graph::Node& n, const glm::dmat4& m) {
        const glm::dmat3 L(m);
        const glm::dvec3 row(L[0][2], L[1][2], L[2][2]);  // world z = row·u + cz
        const double cz = m[3][2];
        if (n.prim == P::Sphere) return sphere(n.p[0], m, row, cz);
        if ((n.prim == P::Cylinder || n.prim == P::Prism) && (straight(n) || across(row)))
            return extrusion(n, m, row, cz);
        if (n.prim == P::Prism) {
            std::vector<Tri> tris;
            if (!tapered_triangles(g_.graph, n, m, tris))
                throw SourceError(n.loc, "projection(cut = true) of a twisted extrusion, or a tapered one of a "
                                         "polygon other than one convex path, across its axis is not supported yet");
            return closed_section(std::move(tris));
        }
        return closed_section(leaf_triangles(g_.graph, n, m, tol_));
    }

    // The section as a closed set: a face lying in z = 0 belongs to it, as in
    // OpenSCAD 2021.01 (`projection(cut = true) cube(2)` is the 2 × 2 bottom
    // face; a difference removes a subtrahend's face, a union keeps both:
    // measured, docs/lowering.md "Projection"). section_loops counts a vertex
    // at z = 0 as above, which keeps a face whose solid lies below; the
    // triangles mirrored in z keep one whose solid lies above. When a vertex
    // lies at 0, the union of both.
    std::uint32_t closed_section(std::vector<Tri> tris) {
        const std::uint32_t below = prism_node(g_, section_loops(tris), loc_);
        bool on = false;
        for (Tri& t : tris) {
            on = on || t.a.z == 0 || t.b.z == 0 || t.c.z == 0;
            t.a.z = -t.a.z, t.b.z = -t.b.z, t.c.z = -t.c.z;
        }
        return on ? either(below, prism_node(g_, section_loops(tris), loc_)) : below;
    }

    std::uint32_t either(std::uint32_t a, std::uint32_t b) {
        if (a == kEmpty || b == kEmpty) return a == kEmpty ? b : a;
        return op_node(g_, NK::Union, {a, b}, loc_);
    }

    // The ball's section is a disc in object space, an ellipse in the world.
    std::uint32_t sphere(double r, const glm::dmat4& m, glm::dvec3 row, double cz) {
        const double k = glm::length(row), delta = -cz / k;
        if (std::abs(delta) >= r) return kEmpty;
        const glm::dvec3 nu = row / k;
        const glm::dvec3 e1 = glm::normalize(std::abs(nu.x) < 0.9 ? glm::cross(nu, {1, 0, 0}) : glm::cross(nu, {0, 1, 0}));
        const glm::dvec3 e2 = glm::cross(nu, e1);
        const glm::dmat3 L(m);
        const glm::dmat2 A{glm::dvec2(L * e1), glm::dvec2(L * e2)};
        return ellipse_node(g_, std::sqrt(r * r - delta * delta), A, xy(m, delta * nu), loc_);
    }

    // A Cylinder or Prism leaf: a 2D section (object x, y) times z0 < z < z1.
    std::uint32_t extrusion(const graph::Node& n, const glm::dmat4& m, glm::dvec3 row, double cz) {
        const double z0 = n.p[0], z1 = n.p[1];
        const glm::dmat3 L(m);
        const bool circle = n.prim == P::Cylinder;
        const double r = std::max(n.p[2], n.p[3]);
        if (std::abs(row.z) > 1e-12 * glm::length(row)) {
            // The plane is a graph over the section: z(x, y) = f·(x, y, 1).
            const glm::dvec3 f(-row.x / row.z, -row.y / row.z, -cz / row.z);
            const glm::dmat2 A(glm::dvec2(L * glm::dvec3(1, 0, f.x)), glm::dvec2(L * glm::dvec3(0, 1, f.y)));
            const glm::dvec2 t = xy(m, {0, 0, f.z});
            if (across(row)) {  // across the axis: the section at one height
                if (f.z < z0 || f.z > z1) return kEmpty;  // closed: an end face in the plane is kept
                const double tau = (f.z - z0) / (z1 - z0);
                if (circle) return ellipse_node(g_, n.p[2] + (n.p[3] - n.p[2]) * tau, A, t, loc_);
                const double a = -n.p[4] * tau, sx = 1 + n.p[2] * tau, sy = 1 + (n.p[2] + n.p[3]) * tau;
                const glm::dmat2 S(glm::dvec2(sx * std::cos(a), sy * std::sin(a)),
                                   glm::dvec2(-sx * std::sin(a), sy * std::cos(a)));
                return mapped(g_, shape(n), A * S, t, loc_);
            }
            const glm::dvec2 lo = circle ? glm::dvec2(-r) : g_.graph.polygons[n.index].lo,
                             hi = circle ? glm::dvec2(r) : g_.graph.polygons[n.index].hi;
            const glm::dvec2 pad = glm::dvec2(1) + (hi - lo);
            const auto band = clip_band({lo - pad, {hi.x + pad.x, lo.y - pad.y}, hi + pad, {lo.x - pad.x, hi.y + pad.y}},
                                        f, z0, z1);
            const std::uint32_t strip = prism_node(g_, {band}, loc_);
            if (strip == kEmpty) return kEmpty;
            return mapped(g_, op_node(g_, NK::Intersection, {shape(n), strip}, loc_), A, t, loc_);
        }
        // The plane contains the axis: along the line ν·(x, y) = c the
        // section's intervals, times z0 < z < z1.
        const glm::dvec2 nxy(row.x, row.y);
        const double k = glm::length(nxy), c = -cz / k;
        const glm::dvec2 nu = nxy / k, d(-nu.y, nu.x), q0 = c * nu;
        if (circle) {
            if (std::abs(c) >= r) return kEmpty;
            const double h = std::sqrt(r * r - c * c);
            return rectangles(m, q0, d, {-h, h}, z0, z1);
        }
        // A side lying on the line counts as in (closed_section's rule): the
        // line's intervals with an end point on it counted on each side in turn.
        std::vector<double> s[2];
        for (const glm::dvec4& e : g_.graph.polygons[n.index].edges) {
            const glm::dvec2 a(e.x, e.y), b(e.z, e.w);
            const double fa = glm::dot(nu, a) - c, fb = glm::dot(nu, b) - c;
            for (int side = 0; side < 2; ++side)
                if (side == 0 ? (fa >= 0) != (fb >= 0) : (fa > 0) != (fb > 0))
                    s[side].push_back(glm::dot(a + (b - a) * (fa / (fa - fb)) - q0, d));
        }
        for (auto& v : s) std::sort(v.begin(), v.end());
        const std::uint32_t first = rectangles(m, q0, d, s[0], z0, z1);
        return s[0] == s[1] ? first : either(first, rectangles(m, q0, d, s[1], z0, z1));
    }

    // The intervals s[0]..s[1], s[2]..s[3], ... of the line q0 + s·d, times z0 < z < z1.
    std::uint32_t rectangles(const glm::dmat4& m, glm::dvec2 q0, glm::dvec2 d, const std::vector<double>& s, double z0,
                             double z1) {
        Loops rects;
        auto w = [&](double si, double z) { return xy(m, glm::dvec3(q0 + si * d, z)); };
        for (std::size_t i = 0; i + 1 < s.size(); i += 2)
            if (s[i] < s[i + 1]) rects.push_back({w(s[i], z0), w(s[i + 1], z0), w(s[i + 1], z1), w(s[i], z1)});
        return prism_node(g_, rects, loc_);
    }

    // The leaf's own 2D section as a flat node (its polygon shared).
    std::uint32_t shape(const graph::Node& n) {
        graph::Node s;
        s.kind = NK::Primitive;
        s.prim = n.prim;
        s.index = n.index;
        s.p[1] = 1;
        if (n.prim == P::Cylinder) s.p[2] = s.p[3] = n.p[2];
        s.loc = loc_;
        s.flat = true;
        return g_.add(std::move(s));
    }
};

// The world box of a subtree (conservative for tessellated leaves).
struct Box3 {
    glm::dvec3 lo{1e300}, hi{-1e300};
    void add(glm::dvec3 p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
};

Box3 subtree_box(const graph::SceneGraph& g, std::uint32_t id, const glm::dmat4& m, double tol) {
    const graph::Node& n = g.nodes[id];
    Box3 b;
    auto child = [&](std::uint32_t k) { return g.child_refs[n.first_child + k]; };
    if (n.kind == NK::Primitive) {
        if (n.prim == P::Cylinder || n.prim == P::Prism || n.prim == P::Sphere) {
            const double grow = n.prim == P::Prism ? std::max({1.0, 1 + n.p[2], 1 + n.p[2] + n.p[3]}) * std::sqrt(2.0) : 1;
            glm::dvec2 lo(-n.p[0]), hi(n.p[0]);
            double z0 = -n.p[0], z1 = n.p[0];
            if (n.prim != P::Sphere) {
                const double r = std::max(n.p[2], n.p[3]);
                lo = n.prim == P::Prism ? g.polygons[n.index].lo * grow : glm::dvec2(-r);
                hi = n.prim == P::Prism ? g.polygons[n.index].hi * grow : glm::dvec2(r);
                if (n.prim == P::Prism) lo = glm::min(lo, -hi), hi = glm::max(hi, -lo);
                z0 = n.p[0], z1 = n.p[1];
            }
            for (int i = 0; i < 8; ++i)
                b.add(glm::dvec3(m * glm::dvec4(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? z1 : z0, 1)));
        } else {
            for (const Tri& t : leaf_triangles(g, n, m, std::max(tol, 0.01))) b.add(t.a), b.add(t.b), b.add(t.c);
        }
        return b;
    }
    if (n.kind == NK::Transform) return subtree_box(g, child(0), m * g.matrices[n.index], tol);
    for (std::uint32_t k = 0; k < n.child_count; ++k) {
        const Box3 c = subtree_box(g, child(k), m, tol);
        if (k == 0 || n.kind == NK::Union || n.kind == NK::Appearance) {
            if (!c.empty()) b.add(c.lo), b.add(c.hi);
        } else if (n.kind == NK::Intersection) {
            b.lo = glm::max(b.lo, c.lo), b.hi = glm::min(b.hi, c.hi);
        }
        if (k == 0 && c.empty() && n.kind != NK::Union) return c;
    }
    return b;
}

bool union_tree(const graph::SceneGraph& g, std::uint32_t id) {
    const graph::Node& n = g.nodes[id];
    if (n.kind == NK::Primitive) return true;
    if (n.kind != NK::Union && n.kind != NK::Transform && n.kind != NK::Appearance) return false;
    for (std::uint32_t k = 0; k < n.child_count; ++k)
        if (!union_tree(g, g.child_refs[n.first_child + k])) return false;
    return true;
}

// The shadow of a union of leaves: exact ellipses as nodes, every
// polygonal piece into `loops` (counter-clockwise, non-zero union) or, for
// a polygon section filled even-odd, into `evenodd`.
class Shadow {
public:
    Shadow(GraphBuilder& g, double tol, const SourceLoc& loc) : g_(g), tol_(tol), loc_(loc) {}
    std::vector<std::uint32_t> nodes;
    Loops loops;
    std::vector<Loops> evenodd;

    void walk(std::uint32_t id, const glm::dmat4& m) {
        const graph::Node n = g_.graph.nodes[id];  // a copy: the walk adds nodes
        if (n.kind == NK::Primitive) return leaf(n, m);
        const glm::dmat4 inner = n.kind == NK::Transform ? m * g_.graph.matrices[n.index] : m;
        for (std::uint32_t k = 0; k < n.child_count; ++k) walk(g_.graph.child_refs[n.first_child + k], inner);
    }

private:
    GraphBuilder& g_;
    double tol_;
    SourceLoc loc_;

    void add_ccw(std::vector<glm::dvec2> p) {
        double area = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const glm::dvec2 a = p[i], b = p[(i + 1) % p.size()];
            area += a.x * b.y - a.y * b.x;
        }
        if (area == 0) return;
        if (area < 0) std::reverse(p.begin(), p.end());
        loops.push_back(std::move(p));
    }

    void leaf(const graph::Node& n, const glm::dmat4& m) {
        const glm::dmat3 L(m);
        const glm::dvec2 c(m[3]);
        if (n.prim == P::Sphere) {  // B·ball: the ellipse with matrix B·Bᵀ = S·Sᵀ (Cholesky)
            const glm::dvec3 r0(L[0][0], L[1][0], L[2][0]), r1(L[0][1], L[1][1], L[2][1]);
            const double q00 = glm::dot(r0, r0), q01 = glm::dot(r0, r1), q11 = glm::dot(r1, r1);
            const double s00 = std::sqrt(q00), s10 = q01 / s00, s11 = std::sqrt(std::max(0.0, q11 - s10 * s10));
            nodes.push_back(ellipse_node(g_, n.p[0], glm::dmat2(glm::dvec2(s00, s10), glm::dvec2(0, s11)), c, loc_));
            return;
        }
        if ((n.prim == P::Cylinder || n.prim == P::Prism) && straight(n)) {
            // The section A(P) at z0 swept along v: both ends and each edge's parallelogram.
            const glm::dmat2 A{glm::dvec2(L[0]), glm::dvec2(L[1])};
            const glm::dvec2 t0 = xy(m, {0, 0, n.p[0]}), v = glm::dvec2(L[2]) * (n.p[1] - n.p[0]);
            if (n.prim == P::Cylinder) {
                const double r = n.p[2];
                const glm::dvec2 w(-v.y, v.x), aw = glm::transpose(A) * w;
                if (std::abs(glm::determinant(A)) > 1e-12 * glm::length(L[0]) * glm::length(L[1])) {
                    nodes.push_back(ellipse_node(g_, r, A, t0, loc_));
                    nodes.push_back(ellipse_node(g_, r, A, t0 + v, loc_));
                    if (glm::length(aw) == 0) return;
                    const glm::dvec2 p = A * (r * aw / glm::length(aw));
                    add_ccw({t0 + p, t0 - p, t0 - p + v, t0 + p + v});
                    return;
                }
            } else {
                const Loops section = polygon_loops(g_.graph.polygons[n.index]);
                for (const glm::dvec2 shift : {glm::dvec2(0), v}) {
                    Loops mappedl = section;
                    for (auto& loop : mappedl)
                        for (auto& p : loop) p = A * p + t0 + shift;
                    evenodd.push_back(std::move(mappedl));
                }
                for (const auto& loop : section)
                    for (std::size_t i = 0; i < loop.size(); ++i) {
                        const glm::dvec2 a = A * loop[i] + t0, b = A * loop[(i + 1) % loop.size()] + t0;
                        add_ccw({a, b, b + v, a + v});
                    }
                return;
            }
        }
        std::vector<Tri> tris;
        if (n.prim == P::Prism && !tapered_triangles(g_.graph, n, m, tris))
            throw SourceError(n.loc, "projection() of a twisted extrusion, or a tapered one of a polygon other than "
                                     "one convex path, is not supported yet");
        if (n.prim != P::Prism) tris = leaf_triangles(g_.graph, n, m, tol_);
        for (const Tri& t : tris) add_ccw({glm::dvec2(t.a), glm::dvec2(t.b), glm::dvec2(t.c)});
    }
};

// Doubles onto Clipper's grid: 2^50 steps across the extent, as region2d.
struct Grid {
    double scale = 1;
    explicit Grid(double extent) : scale(extent > 0 ? std::ldexp(1.0, 50 - std::ilogb(extent) - 1) : 1) {}
    ClipperLib::Paths paths(const Loops& loops) const {
        ClipperLib::Paths out;
        for (const auto& loop : loops) {
            out.emplace_back();
            for (glm::dvec2 p : loop)
                out.back().push_back({ClipperLib::cInt(std::llround(p.x * scale)), ClipperLib::cInt(std::llround(p.y * scale))});
        }
        return out;
    }
    Loops loops(const ClipperLib::Paths& paths) const {
        Loops out;
        for (const auto& path : paths) {
            out.emplace_back();
            for (const auto& p : path) out.back().push_back(glm::dvec2(double(p.X), double(p.Y)) / scale);
        }
        return out;
    }
};

ClipperLib::Paths unite(const ClipperLib::Paths& a, const ClipperLib::Paths& b, ClipperLib::PolyFillType fill) {
    ClipperLib::Clipper c;
    c.AddPaths(a, ClipperLib::ptSubject, true);
    c.AddPaths(b, ClipperLib::ptClip, true);
    ClipperLib::Paths out;
    c.Execute(ClipperLib::ctUnion, out, fill, fill);
    return out;
}

double extent_of(const Box3& b) {
    return std::max({std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.hi.x), std::abs(b.hi.y)});
}

std::uint32_t shadow(GraphBuilder& g, std::uint32_t root, double tol, const SourceLoc& loc) {
    const Box3 box = subtree_box(g.graph, root, glm::dmat4(1.0), tol);
    if (box.empty()) return kEmpty;
    const Grid grid(extent_of(box) * 1.01);
    ClipperLib::Paths acc;
    std::vector<std::uint32_t> parts;
    if (union_tree(g.graph, root)) {
        Shadow s(g, tol, loc);
        s.walk(root, glm::dmat4(1.0));
        for (const Loops& e : s.evenodd) acc = unite(acc, unite(grid.paths(e), {}, ClipperLib::pftEvenOdd), ClipperLib::pftNonZero);
        acc = unite(acc, grid.paths(s.loops), ClipperLib::pftNonZero);
        parts = s.nodes;
    } else {
        const int slices = int(std::ceil(1 / std::sqrt(std::min(tol, 0.25))));
        for (int k = 0; k < slices; ++k) {
            const double z = box.lo.z + (box.hi.z - box.lo.z) * (k + 0.5) / slices;
            const auto n0 = g.graph.nodes.size(), c0 = g.graph.child_refs.size(), m0 = g.graph.matrices.size(),
                       p0 = g.graph.polygons.size();
            glm::dmat4 down(1.0);
            down[3][2] = -z;
            const std::uint32_t id = Sectioner(g, tol, loc).walk(root, down);
            if (id != kEmpty) {
                const std::uint32_t roots[] = {id};
                const Region2 r = flatten_region(g.graph, roots, 0, tol, loc);
                Loops l;
                for (const auto& path : r.paths) {
                    l.emplace_back();
                    for (const auto& p : path) l.back().push_back(r.point(p));
                }
                acc = unite(acc, grid.paths(l), ClipperLib::pftNonZero);
            }
            g.graph.nodes.resize(n0), g.graph.child_refs.resize(c0), g.graph.matrices.resize(m0), g.graph.polygons.resize(p0);
        }
    }
    const std::uint32_t poly = prism_node(g, grid.loops(acc), loc);
    if (poly != kEmpty) parts.push_back(poly);
    if (parts.empty()) return kEmpty;
    return parts.size() == 1 ? parts[0] : op_node(g, NK::Union, parts, loc);
}

void projection_call(ModuleCall& c) {
    const bool cut = arg_bool(c.args, 0, "cut", false);
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    {
        GhostFrameScope hide(c.state(), "projection");
        c.children();
    }
    std::vector<std::uint32_t> solids;
    for (std::size_t i = mark; i < g.pending.size(); ++i) {
        const graph::Node& n = g.graph.nodes[g.pending[i]];
        if (!n.flat)
            solids.push_back(g.pending[i]);
        else if (c.lenient())
            c.warn("ignoring a 2D child (projection projects 3D solids)");
        else
            throw SourceError(n.loc, "projection: projects 3D solids, not 2D shapes");
    }
    g.pending.resize(mark);
    if (solids.empty()) return;
    std::uint32_t root = solids[0];
    if (solids.size() > 1) {
        root = op_node(g, NK::Union, solids, c.st.loc);
        g.graph.nodes[root].flat = false;
    }
    if (has_geometry_ops(g.graph, root)) {
        // Their results exist only once lowering has built them: a copy of
        // the subtree goes through lowering's resolver and the ordinary nodes
        // it gives back are projected (docs/lowering.md, "Projection").
        if (!c.geometry_ops())
            throw SourceError(c.st.loc, "projection() of hull(), minkowski() or resize() needs lowering's "
                                        "resolver, which this caller did not give");
        graph::SceneGraph resolved;
        if (c.geometry_ops()(extract_subtree(g.graph, root), resolved)) root = append_graph(g, std::move(resolved));
    }
    try {
        const std::uint32_t out = cut ? Sectioner(g, c.curve_tolerance(), c.st.loc).walk(root, glm::dmat4(1.0))
                                      : shadow(g, root, c.curve_tolerance(), c.st.loc);
        if (out != kEmpty) g.push(out);
    } catch (const ClipperLib::clipperException& e) {
        throw SourceError(c.st.loc, std::string("projection: ") + e.what());
    }
}

const ModuleEntry kProjection[] = {
    {"projection", ModuleKind::Operation, {"cut", "convexity"}, projection_call},
};

}  // namespace

std::span<const ModuleEntry> projection_modules() { return kProjection; }

}  // namespace kerf::eval

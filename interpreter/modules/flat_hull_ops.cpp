#include "interpreter/modules/flat_hull_ops.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "grammar/source.hpp"

namespace kerf::eval {

namespace {

using NK = graph::NodeKind;
using P = csg::PrimKind;

// Lowering's limits on a Minkowski sum (lower/geometry_ops.cpp).
constexpr std::size_t kMaxPieces = 4096;
constexpr std::size_t kMaxSumPoints = 4'000'000;

double turn(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Andrew's monotone chain: the corners counter-clockwise, collinear points
// dropped; fewer than 3 when the points span no area.
ConvexPolygon hull2(std::vector<glm::dvec2> p) {
    std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (p.size() < 3) return p;
    ConvexPolygon h(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

struct Box2 {
    glm::dvec2 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
    bool empty() const { return !(lo.x <= hi.x); }
    void add(const Box2& b) { lo = glm::min(lo, b.lo), hi = glm::max(hi, b.hi); }
};

class Plane {
public:
    explicit Plane(const graph::SceneGraph& g) : g_(g) {}

    // The convex point sets of 2D subtree `id` under `a`, appended to `out`.
    void pieces(std::uint32_t id, const Map2& a, double tol, std::vector<ConvexPolygon>& out) {
        const graph::Node& n = g_.nodes[id];
        if (n.kind == NK::Primitive) {
            out.push_back(leaf_points(n, a, tol));
        } else if (n.kind == NK::Hull || (n.kind == NK::Minkowski && n.child_count > 1)) {
            for (ConvexPolygon& q : parts(id)) {
                for (glm::dvec2& v : q) v = apply(a, v);
                out.push_back(std::move(q));
            }
        } else if (n.kind == NK::Resize) {
            if (n.child_count > 0) pieces(child(n, 0), a * resize_map(id), tol, out);
        } else {
            const Map2 inner = n.kind == NK::Transform ? a * plane_part(g_.matrices[n.index]) : a;
            const bool first = n.kind == NK::Difference || n.kind == NK::Intersection;
            for (std::uint32_t k = 0; k < (first ? std::min(n.child_count, 1u) : n.child_count); ++k)
                pieces(child(n, k), inner, tol, out);
        }
    }

    std::vector<ConvexPolygon> parts(std::uint32_t id) {
        const graph::Node& n = g_.nodes[id];
        const double tol = n.p[0];
        std::vector<ConvexPolygon> ps;
        for (std::uint32_t k = 0; k < n.child_count; ++k) pieces(child(n, k), Map2(1.0), tol, ps);
        std::vector<ConvexPolygon> out;
        if (n.kind == NK::Hull) {
            std::vector<glm::dvec2> all;
            for (const ConvexPolygon& p : ps) all.insert(all.end(), p.begin(), p.end());
            out.push_back(hull2(std::move(all)));
        } else {
            out = minkowski(n, tol);
        }
        std::erase_if(out, [](const ConvexPolygon& p) { return p.size() < 3; });
        return out;
    }

    // Per child its pieces, every combination of one per child summed
    // (corners pairwise) and hulled; empty children skipped, as OpenSCAD does.
    std::vector<ConvexPolygon> minkowski(const graph::Node& n, double tol) {
        std::vector<ConvexPolygon> sums{{glm::dvec2(0)}};
        for (std::uint32_t k = 0; k < n.child_count; ++k) {
            std::vector<ConvexPolygon> ps;
            pieces(child(n, k), Map2(1.0), tol, ps);
            if (ps.empty()) continue;
            if (sums.size() * ps.size() > kMaxPieces)
                throw SourceError(n.loc, "minkowski: " + std::to_string(sums.size() * ps.size()) +
                                             " convex pieces, more than kerf builds (" + std::to_string(kMaxPieces) + ")");
            std::vector<ConvexPolygon> next;
            for (ConvexPolygon& q : ps) q = hull2(std::move(q));
            for (const ConvexPolygon& x : sums)
                for (const ConvexPolygon& y : ps) {
                    if (x.size() * y.size() > kMaxSumPoints)
                        throw SourceError(n.loc, "minkowski: a sum of " + std::to_string(x.size()) + " and " +
                                                     std::to_string(y.size()) +
                                                     " points is too large; a coarser --curve-tolerance makes fewer");
                    std::vector<glm::dvec2> s;
                    s.reserve(x.size() * y.size());
                    for (glm::dvec2 u : x)
                        for (glm::dvec2 v : y) s.push_back(u + v);
                    next.push_back(hull2(std::move(s)));
                }
            sums = std::move(next);
        }
        return sums;
    }

    Map2 resize_map(std::uint32_t id) {
        const graph::Node& n = g_.nodes[id];
        Map2 m(1.0);
        if (n.child_count == 0) return m;
        const Box2 b = box(child(n, 0), Map2(1.0));
        if (b.empty()) return m;
        const glm::dvec2 size = b.hi - b.lo;
        glm::dvec2 scale(1);
        int largest = 0;
        for (int i = 0; i < 2; ++i) {
            if (n.p[i] == 0) continue;
            if (size[i] == 0) return m;
            scale[i] = n.p[i] / size[i];
            if (n.p[i] > n.p[largest]) largest = i;
        }
        const double autoscale = n.p[largest] != 0 ? n.p[largest] / size[largest] : 1;
        for (int i = 0; i < 2; ++i)
            if (n.p[3 + i] != 0 && n.p[i] == 0) scale[i] = autoscale;
        m[0][0] = scale.x, m[1][1] = scale.y;
        return m;
    }

private:
    const graph::SceneGraph& g_;

    std::uint32_t child(const graph::Node& n, std::uint32_t k) const { return g_.child_refs[n.first_child + k]; }

    ConvexPolygon leaf_points(const graph::Node& n, const Map2& a, double tol) const {
        ConvexPolygon pts;
        if (n.prim == P::Box) {
            pts = {{n.p[0], n.p[1]}, {n.p[3], n.p[1]}, {n.p[3], n.p[4]}, {n.p[0], n.p[4]}};
        } else if (n.prim == P::Prism) {
            for (const glm::dvec4& e : g_.polygons[n.index].edges) pts.push_back({e.x, e.y});
        } else if (n.prim == P::Cylinder) {
            circle_chords(n.p[2], tol, [&](glm::dvec2 p, glm::dvec2) { pts.push_back(p); });
        } else {
            throw SourceError(n.loc, "this shape has no 2D outline");
        }
        for (glm::dvec2& p : pts) p = apply(a, p);
        return pts;
    }

    // The box lowering gives the 2D subtree `id` under `a`: exact for the
    // leaves (a circle's mapped ellipse), a union's the union of its
    // members', an intersection's the clipped box, a difference's its
    // minuend's; a hull's the box of its pieces, a sum's the sum of boxes.
    Box2 box(std::uint32_t id, const Map2& a) {
        const graph::Node& n = g_.nodes[id];
        Box2 b;
        if (n.kind == NK::Primitive && n.prim == P::Cylinder) {
            const glm::dvec2 c = apply(a, {0, 0});
            const glm::dvec2 half = n.p[2] * glm::dvec2(std::hypot(a[0][0], a[1][0]), std::hypot(a[0][1], a[1][1]));
            return {c - half, c + half};
        }
        if (n.kind == NK::Primitive) {
            for (glm::dvec2 p : leaf_points(n, a, 0.5)) b.add({p, p});
            return b;
        }
        if (n.kind == NK::Resize) return n.child_count > 0 ? box(child(n, 0), a * resize_map(id)) : b;
        if (n.kind == NK::Minkowski && n.child_count > 1) {
            Box2 sum{glm::dvec2(0), glm::dvec2(0)};
            bool any = false;
            for (std::uint32_t k = 0; k < n.child_count; ++k) {
                const Box2 c = piece_box(child(n, k), Map2(1.0));
                if (c.empty()) continue;
                sum.lo += c.lo, sum.hi += c.hi, any = true;
            }
            if (!any) return b;
            // The sum in its own frame, mapped: the box of the mapped corners.
            for (glm::dvec2 p : {sum.lo, sum.hi, glm::dvec2(sum.lo.x, sum.hi.y), glm::dvec2(sum.hi.x, sum.lo.y)})
                b.add({apply(a, p), apply(a, p)});
            return b;
        }
        if (n.kind == NK::Hull) return piece_box(id, a, true);
        const Map2 inner = n.kind == NK::Transform ? a * plane_part(g_.matrices[n.index]) : a;
        if (n.kind == NK::Difference) return n.child_count > 0 ? box(child(n, 0), inner) : b;
        for (std::uint32_t k = 0; k < n.child_count; ++k) {
            const Box2 c = box(child(n, k), inner);
            if (n.kind == NK::Intersection && k > 0)
                b.lo = glm::max(b.lo, c.lo), b.hi = glm::min(b.hi, c.hi);
            else
                b.add(c);
        }
        return b;
    }

    // The box of the pieces of `id` (children of a hull or sum): a
    // difference or intersection by its first operand.
    Box2 piece_box(std::uint32_t id, const Map2& a, bool children = false) {
        const graph::Node& n = g_.nodes[id];
        if (!children && n.kind != NK::Difference && n.kind != NK::Intersection && n.kind != NK::Union &&
            n.kind != NK::Transform && n.kind != NK::Appearance)
            return box(id, a);
        const Map2 inner = n.kind == NK::Transform ? a * plane_part(g_.matrices[n.index]) : a;
        const bool first = n.kind == NK::Difference || n.kind == NK::Intersection;
        Box2 b;
        for (std::uint32_t k = 0; k < (first ? std::min(n.child_count, 1u) : n.child_count); ++k)
            b.add(piece_box(child(n, k), inner));
        return b;
    }
};

}  // namespace

std::vector<ConvexPolygon> flat_convex_parts(const graph::SceneGraph& g, std::uint32_t id) { return Plane(g).parts(id); }

Map2 flat_resize_map(const graph::SceneGraph& g, std::uint32_t id) { return Plane(g).resize_map(id); }

}  // namespace kerf::eval

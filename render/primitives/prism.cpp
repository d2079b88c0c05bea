// Ray against a prism: the z slab gives the chord, the section's edges the
// crossings of the ray's projection on the plane, and parity (even-odd) the
// spans. Which edges a line crosses is decided by the sides of their end
// points (half-open: a point on the line counts as the minus side), the
// same test for the two edges at a vertex, so a line through a vertex or
// along an edge never miscounts; only where it crosses comes from a
// division. The ray is shifted to its point closest to the section's
// centre first, so a far ray does not cancel in the differences.
#include "render/primitives/prism.hpp"

#include <algorithm>
#include <cmath>

#include <vector>

#include "render/primitives/kinds.hpp"
#include "render/primitives/prism_grid.hpp"

namespace kerf::csg {

namespace {

template <typename T>
T cross2(T ax, T ay, T bx, T by) { return ax * by - ay * bx; }

// Calls test(i) once for each edge the grid lists near the line c + s·d in
// the plane: every edge the line may cross. The edge test in T decides a
// side to within about 5 ulps of T of (|vertex| + |c|) (the vertices
// rounded to T, the differences, the cross product); the walk's margin is
// a dozen times that, which also covers the walk's own round-off in
// double. An edge in several cells is tested once (a per-thread stamp per
// edge).
template <typename T, class Test>
void for_grid_edges(const PrismGrid& g, const Polygon2& poly, const glm::vec<3, T>& c, glm::dvec2 d,
                    const Test& test) {
    thread_local std::vector<std::uint32_t> seen;
    thread_local std::uint32_t ray = 0;
    if (seen.size() < poly.edges.size()) seen.resize(poly.edges.size(), 0);
    if (++ray == 0) {
        std::fill(seen.begin(), seen.end(), 0);
        ray = 1;
    }
    const double m = 64 * double(std::numeric_limits<T>::epsilon()) *
                     (g.reach + std::abs(double(c.x)) + std::abs(double(c.y)));
    walk_prism_grid(g, glm::dvec2(c.x, c.y), d, m, [&](const std::uint32_t* e, const std::uint32_t* end) {
        for (; e != end; ++e) {
            const std::uint32_t i = *e;
            if (seen[i] == ray) continue;
            seen[i] = ray;
            test(i);
        }
    });
}

template <typename T>
int straight_prism(const Polygon2& poly, const PrismGrid* grid, const double* p, const glm::vec<3, T>& o,
                   const glm::vec<3, T>& d, PrismSpan<T>* out, PrismCrossing<T>* scratch, T wa, T wb) {
    constexpr T inf = std::numeric_limits<T>::infinity();
    const glm::dvec2 mid = 0.5 * (poly.lo + poly.hi);
    const glm::vec<3, T> centre(T(mid.x), T(mid.y), T(0.5 * (p[0] + p[1])));
    const T tc = closest_t(o, d, centre);
    const glm::vec<3, T> c = o + tc * d;
    // The slab, in s = t - tc.
    T sa = -inf, sb = inf;
    std::uint8_t pa = kPartNone, pb = kPartNone;
    const T z0 = T(p[0]), z1 = T(p[1]);
    if (d.z != T(0)) {
        sa = (z0 - c.z) / d.z;
        sb = (z1 - c.z) / d.z;
        pa = kPartBottom;
        pb = kPartTop;
        if (d.z < T(0)) {
            std::swap(sa, sb);
            std::swap(pa, pb);
        }
        if (!(sa < sb)) return 0;
    } else if (!(z0 < c.z && c.z < z1)) {
        return 0;  // parallel to the caps and not strictly between them
    }
    const T lo = std::max(sa, wa - tc), hi = std::min(sb, wb - tc);
    if (!(lo <= hi)) return 0;
    const PrismEnd<T> cap0{sa, pa, 0}, cap1{sb, pb, 0};
    int n = 0;
    if (d.x == T(0) && d.y == T(0)) {
        // Parallel to the sides: inside the whole chord or not at all (a ray
        // towards +x from the point, with the same half-open vertex rule).
        bool inside = false;
        auto test_edge = [&](std::uint32_t i) {
            const glm::dvec4& e = poly.edges[i];
            const T ay = T(e.y) - c.y, by = T(e.w) - c.y;
            if ((ay > T(0)) == (by > T(0))) return;
            const T ax = T(e.x) - c.x, bx = T(e.z) - c.x;
            // x where the edge meets y = c.y, compared with c.x by sign alone.
            inside ^= (cross2(ax, ay, bx, by) > T(0)) == (by > ay);
        };
        if (grid && !grid->empty()) {
            for_grid_edges(*grid, poly, c, glm::dvec2(1, 0), test_edge);  // the row through c
        } else {
            for (std::uint32_t i = 0; i < poly.edges.size(); ++i) test_edge(i);
        }
        if (inside) emit_prism_span(out, n, tc, cap0, cap1);
        return n;
    }
    // Crossings: before lo they only set the parity at lo (and the last one
    // may start the first span); after hi only the first may end the last.
    // The parity at lo, the last crossing before it and the first after
    // hi, and the count of crossings in between. Kept in a local struct
    // handed to the edge test, so that the loop over every edge keeps it
    // in registers (through one captured by reference, which the grid
    // walk's callback also uses, it went to memory: small sections tested
    // 1.5-2x slower).
    struct Parity {
        bool inside = false;
        PrismEnd<T> before{-inf, kPartNone, 0}, after{inf, kPartNone, 0};
        bool before_plus = false, after_plus = false;
        int k = 0;
    };
    const T inv_dd = T(1) / (d.x * d.x + d.y * d.y);
    auto test_edge = [&poly, &c, &d, lo, hi, inv_dd, scratch](Parity& q, std::uint32_t i) {
        const glm::dvec4& e = poly.edges[i];
        const T ax = T(e.x) - c.x, ay = T(e.y) - c.y, bx = T(e.z) - c.x, by = T(e.w) - c.y;
        const T sa_ = cross2(d.x, d.y, ax, ay), sb_ = cross2(d.x, d.y, bx, by);
        if ((sa_ > T(0)) == (sb_ > T(0))) return;
        // Where: the fraction of the edge at which its end points' signed
        // distances to the line change sign, projected on the ray. The
        // divisor sa_ - sb_ is never 0 (the signs differ), and the crossing
        // stays between the end points' projections even for an edge
        // almost along the ray, where a line–line division would be
        // ill-conditioned (or 0/0).
        const T pa_ = ax * d.x + ay * d.y, pb_ = bx * d.x + by * d.y;  // projections times |d_xy|²
        const T f = sa_ / (sa_ - sb_);
        const T s = (pa_ + f * (pb_ - pa_)) * inv_dd;
        const bool plus = sb_ > sa_;  // cross(d, edge) > 0
        // Ties go to the lower edge index, so the answer does not depend
        // on the order the edges are tested in (all, or a grid's cells).
        if (s < lo) {
            q.inside = !q.inside;
            if (s > q.before.s || (s == q.before.s && i < q.before.edge)) {
                q.before = {s, kPartNone, i};
                q.before_plus = plus;
            }
        } else if (s > hi) {
            if (s < q.after.s || (s == q.after.s && i < q.after.edge)) {
                q.after = {s, kPartNone, i};
                q.after_plus = plus;
            }
        } else {
            scratch[q.k++] = PrismCrossing<T>{s, i, plus};
        }
    };
    Parity q;
    if (grid && !grid->empty()) {
        Parity g;
        for_grid_edges(*grid, poly, c, glm::dvec2(d.x, d.y), [&](std::uint32_t i) { test_edge(g, i); });
        q = g;
    } else {
        for (std::uint32_t i = 0; i < poly.edges.size(); ++i) test_edge(q, i);
    }
    bool inside = q.inside;
    const PrismEnd<T> before = q.before, after = q.after;
    const bool before_plus = q.before_plus, after_plus = q.after_plus;
    const int k = q.k;
    std::sort(scratch, scratch + k, [](const PrismCrossing<T>& x, const PrismCrossing<T>& y) {
        return x.s < y.s || (x.s == y.s && x.edge < y.edge);
    });
    PrismEnd<T> start = cap0;
    if (inside && before.s > sa) start = {before.s, edge_part(before_plus, true), before.edge};
    for (int j = 0; j < k; ++j) {
        const PrismCrossing<T>& x = scratch[j];
        if (!inside) {
            start = x.s > sa ? PrismEnd<T>{x.s, edge_part(x.plus, true), x.edge} : cap0;
        } else {
            const PrismEnd<T> end = x.s < sb ? PrismEnd<T>{x.s, edge_part(x.plus, false), x.edge} : cap1;
            emit_prism_span(out, n, tc, start, end);
        }
        inside = !inside;
    }
    if (inside) {
        const PrismEnd<T> end = after.s < sb ? PrismEnd<T>{after.s, edge_part(after_plus, false), after.edge} : cap1;
        emit_prism_span(out, n, tc, start, end);
    }
    return n;
}

// A tapered prism (p[2] = g ≠ 0: the section at z is k(z) = 1 + g·(z − z0)/h
// times the polygon) is the straight prism of height h / (1 + g) seen
// through the projective map P(x, y, z) = (x, y, z0 + (z − z0)) / k(z)
// (the z0 offset aside), which maps lines to lines and k > 0 keeps the slab
// in one piece. So the chord of the slab is mapped, the straight prism
// solved on its image with parameter u in [0, 1], and each crossing mapped
// back to the ray's t (the map of u to the chord's λ is a Möbius one);
// caps keep their exact slab t.
template <typename T>
int tapered_prism(const Polygon2& poly, const PrismGrid* grid, const double* p, const glm::vec<3, T>& o,
                  const glm::vec<3, T>& d, PrismSpan<T>* out, PrismCrossing<T>* scratch) {
    const T z0 = T(p[0]), z1 = T(p[1]), g = T(p[2]), h = T(p[1] - p[0]);
    auto k_of = [&](T z) { return T(1) + g * (z - z0) / h; };
    auto warp = [&](const glm::vec<3, T>& x, T k) { return glm::vec<3, T>(x.x / k, x.y / k, z0 + (x.z - z0) / k); };
    const double q[6] = {p[0], p[0] + (p[1] - p[0]) / (1 + p[2]), 0, 0, 0, 0};
    if (d.z == T(0)) {
        // Parallel to the caps: one section all along, the straight prism scaled by k.
        if (!(z0 < o.z && o.z < z1)) return 0;
        const T k = k_of(o.z);
        return straight_prism(poly, grid, q, warp(o, k), d / k, out, scratch, -std::numeric_limits<T>::infinity(),
                              std::numeric_limits<T>::infinity());
    }
    T ta = (z0 - o.z) / d.z, tb = (z1 - o.z) / d.z;
    if (ta > tb) std::swap(ta, tb);
    if (!(ta < tb)) return 0;
    const glm::vec<3, T> A = o + ta * d, B = o + tb * d;
    const T kA = k_of(d.z > T(0) ? z0 : z1), kB = k_of(d.z > T(0) ? z1 : z0);
    glm::vec<3, T> Ap = warp(A, kA), Bp = warp(B, kB);
    Ap.z = T(d.z > T(0) ? q[0] : q[1]);  // the chord's ends lie on the caps
    Bp.z = T(d.z > T(0) ? q[1] : q[0]);
    const int n = straight_prism(poly, grid, q, Ap, Bp - Ap, out, scratch, -std::numeric_limits<T>::infinity(),
                                 std::numeric_limits<T>::infinity());
    int m = 0;
    for (int i = 0; i < n; ++i) {
        PrismSpan<T> s = out[i];
        auto back = [&](T u, std::uint8_t part) {
            if (part == kPartBottom || part == kPartTop) return (part == kPartBottom) == (d.z > T(0)) ? ta : tb;
            const T lambda = u * kA / (kB + u * (kA - kB));
            return ta + lambda * (tb - ta);
        };
        s.s.t0 = back(s.s.t0, s.s.part0);
        s.s.t1 = back(s.s.t1, s.s.part1);
        if (!(s.s.t0 < s.s.t1)) continue;
        if (m > 0 && !(out[m - 1].s.t1 < s.s.t0)) {
            out[m - 1].s.t1 = s.s.t1;
            out[m - 1].s.part1 = s.s.part1;
            out[m - 1].edge1 = s.edge1;
            continue;
        }
        out[m++] = s;
    }
    return m;
}

}  // namespace

template <typename T>
int intersect_prism(const Polygon2& poly, const double* p, const glm::vec<3, T>& o, const glm::vec<3, T>& d,
                    PrismSpan<T>* out, PrismCrossing<T>* scratch, T wa, T wb, const PrismGrid* grid) {
    if (is_swept(p)) return intersect_swept_prism(poly, p, o, d, out, int(prism_span_room(poly.edges.size(), p)));
    if (p[2] != 0) return tapered_prism(poly, grid, p, o, d, out, scratch);
    return straight_prism(poly, grid, p, o, d, out, scratch, wa, wb);
}

glm::dvec3 normal_prism(const Polygon2& poly, const double* p, std::uint8_t part, std::uint32_t edge,
                        const glm::dvec3& x) {
    if (is_swept(p)) return normal_swept_prism(poly, p, part, edge, x);
    if (part == kPartBottom) return {0, 0, -1};
    if (part == kPartTop) return {0, 0, 1};
    if (edge >= poly.edges.size()) return {0, 0, 1};
    const glm::dvec4& e = poly.edges[edge];
    const double ex = e.z - e.x, ey = e.w - e.y;
    // The side through the edge at z0 and its copy scaled by 1 + g at z1:
    // normal to the edge and to the generator from a = (e.x, e.y) to (1 + g)·a.
    const double nz = -p[2] * (e.x * ey - e.y * ex) / (p[1] - p[0]);
    const glm::dvec3 n(ey, -ex, nz);
    return part == kPartEdgeFlipped ? -n : n;
}

template int intersect_prism<float>(const Polygon2&, const double*, const glm::vec<3, float>&, const glm::vec<3, float>&,
                                    PrismSpan<float>*, PrismCrossing<float>*, float, float, const PrismGrid*);
template int intersect_prism<double>(const Polygon2&, const double*, const glm::vec<3, double>&,
                                     const glm::vec<3, double>&, PrismSpan<double>*, PrismCrossing<double>*, double,
                                     double, const PrismGrid*);

}  // namespace kerf::csg

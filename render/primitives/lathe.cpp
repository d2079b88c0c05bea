// Ray against a lathe. Along the ray the point's radius and height trace a
// curve in the (ρ, z) half-plane, and the ray is inside exactly where that
// curve is inside the section (even-odd), so the spans come from the
// curve's crossings with the edges, sorted, by parity from outside at
// t = −∞. As in the prism, WHICH edges the curve crosses is decided from
// the end points alone — a vertex is on the outer side when its radius
// exceeds the curve's at its height, the same test for both edges at that
// vertex (half-open), so a ray through a vertex circle never miscounts —
// and only WHERE comes from solving: an edge whose ends lie on either side
// is crossed once (the root nearest its z range), one whose ends lie on one
// side twice or not at all (both roots strictly inside its range, or
// none), which keeps the parity whatever the rounding.
//
// Edge (r0, z0)–(r1, z1) with z0 ≠ z1 is the cone ρ = α + β·s along the
// ray (s from the shifted origin c, ρ(s)² = |c_xy + s·d_xy|²):
//   (|d_xy|² − β²)·s² + 2(c_xy·d_xy − αβ)·s + |c_xy|² − α² = 0;
// a horizontal edge is an annulus met where z(s) = z0. A ray parallel to
// the caps (d_z = 0) runs along one height: each edge crossing that height
// at radius ρ_e is met twice, at s = ±sqrt(ρ_e² − ρ_min²)/|d_xy|.
#include "render/primitives/lathe.hpp"

#include <algorithm>
#include <cmath>

#include "render/primitives/kinds.hpp"

namespace kerf::csg {

namespace {

// The ray's squared radius at s: g(s) = cc + 2·cd·s + dd·s².
template <typename T>
struct RadiusCurve {
    T cc, cd, dd;
    // Never below 0 (rounding near the axis), so a vertex on the axis is
    // never outside: an axis edge's two ends always agree.
    T at(T s) const { return std::max(cc + s * (T(2) * cd + s * dd), T(0)); }
};

// Roots of a·s² + 2·hb·s + c; returns how many (0, 1 or 2).
template <typename T>
int roots(T a, T hb, T c, T r[2]) {
    if (a == T(0)) {
        if (hb == T(0)) return 0;
        r[0] = -c / (T(2) * hb);
        return 1;
    }
    const T disc = discriminant(hb, a, c);
    if (disc < T(0)) return 0;
    const T q = -(hb + std::copysign(std::sqrt(disc), hb));
    if (q == T(0)) {  // hb = disc = 0: a double root at 0... or c = 0 too
        r[0] = T(0);
        return 1;
    }
    r[0] = q / a;
    r[1] = c / q;
    if (r[0] > r[1]) std::swap(r[0], r[1]);
    return 2;
}

template <typename T>
int sweep_edges(const Polygon2& poly, const glm::vec<3, T>& c, const glm::vec<3, T>& d, PrismCrossing<T>* x) {
    const RadiusCurve<T> g{c.x * c.x + c.y * c.y, c.x * d.x + c.y * d.y, d.x * d.x + d.y * d.y};
    int k = 0;
    for (std::uint32_t i = 0; i < poly.edges.size(); ++i) {
        const glm::dvec4& e = poly.edges[i];
        const T r0 = T(e.x), z0 = T(e.y), r1 = T(e.z), z1 = T(e.w);
        const T dr = r1 - r0, dz = z1 - z0;
        // An edge along the axis sweeps no surface (both ends on one side of
        // every curve, so skipping it keeps the parity).
        if (r0 == T(0) && r1 == T(0)) continue;
        // The vertices' sides of the curve: outside it (ρ larger) or not.
        const T s0 = (z0 - c.z) / d.z, s1 = (z1 - c.z) / d.z;
        const bool out0 = r0 * r0 > g.at(s0), out1 = r1 * r1 > g.at(s1);
        // +perp of the edge, (dz, −dr) in (ρ, z), faces along d where
        // dz·(x_xy·d_xy)/ρ − dr·d_z > 0 (x the point, ρ its radius).
        auto plus = [&](T s, T rho) { return dz * (g.cd + s * g.dd) > dr * d.z * rho; };
        if (dz == T(0)) {
            if (out0 != out1) x[k++] = {s0, i, -dr * d.z > T(0)};
            continue;
        }
        // q(s) = g(s) − ρ_e(s)² = a·s² + 2·hb·s + cq, negative where the
        // cone's radius exceeds the curve's (an "out" vertex: q < 0).
        const T beta = dr / dz * d.z, alpha = r0 + dr / dz * (c.z - z0);
        const T a = g.dd - beta * beta, hb = g.cd - alpha * beta, cq = g.cc - alpha * alpha;
        T r[2] = {0, 0};  // roots() fills as many as it returns; zeroed for the compiler's flow analysis
        const int m = roots(a, hb, cq, r);
        const T lo = std::min(s0, s1), hi = std::max(s0, s1);
        auto rho_at = [&](T s) { return std::max(alpha + beta * s, T(0)); };
        auto add = [&](T s) {
            s = std::clamp(s, lo, hi);
            x[k++] = {s, i, plus(s, rho_at(s))};
        };
        if (out0 != out1) {
            // Exactly one root lies on the edge: the one where q crosses
            // from its sign at lo to its sign at hi (rising: the larger root
            // when a > 0), kept within the range. Chosen by that slope, not
            // by which root landed inside, so two edges through one vertex
            // (or along one line) pick the same root.
            const bool rising = !(s1 >= s0 ? out1 : out0);  // q > 0 at hi
            T s = m == 0 ? (a != T(0) ? -hb / a : (lo + hi) / T(2)) : r[0];
            if (m == 2 && rising == (a > T(0))) s = r[1];
            add(s);
        } else if (m == 2 && a != T(0)) {
            // Both ends on one side: two crossings exactly when q's extremum
            // lies on the edge with the other sign (q there is −disc/a, so
            // the sign of a decides once the roots are real). Decided by the
            // extremum, not by whether each root landed inside the range, so
            // a root rounded just past a vertex still pairs with its partner.
            const T smid = -hb / a;
            if (lo < smid && smid < hi && (a > T(0)) != out0) add(r[0]), add(r[1]);
        }
    }
    return k;
}

// d_z = 0: the ray stays at height c.z; c is its point nearest the axis.
template <typename T>
int level_edges(const Polygon2& poly, const glm::vec<3, T>& c, const glm::vec<3, T>& d, PrismCrossing<T>* x) {
    const T dd = d.x * d.x + d.y * d.y, cd = c.x * d.x + c.y * d.y;
    if (!(dd > T(0))) return 0;
    const T mid = -cd / dd;
    const T rmin2 = std::max(c.x * c.x + c.y * c.y - cd * cd / dd, T(0));
    int k = 0;
    for (std::uint32_t i = 0; i < poly.edges.size(); ++i) {
        const glm::dvec4& e = poly.edges[i];
        const T r0 = T(e.x), z0 = T(e.y), r1 = T(e.z), z1 = T(e.w);
        if ((z0 > c.z) == (z1 > c.z)) continue;  // half-open, as the oracle's point-in-polygon
        const T re = r0 + (c.z - z0) / (z1 - z0) * (r1 - r0);
        if (!(re * re > rmin2)) continue;
        const T h = std::sqrt((re * re - rmin2) / dd);
        // +perp faces along d where dz·(x_xy·d_xy) > 0: on the way out (s > mid).
        const bool up = z1 > z0;
        x[k++] = {mid - h, i, !up};
        x[k++] = {mid + h, i, up};
    }
    return k;
}

}  // namespace

template <typename T>
int intersect_lathe(const Polygon2& poly, const glm::vec<3, T>& o, const glm::vec<3, T>& d, PrismSpan<T>* out,
                    PrismCrossing<T>* scratch) {
    // Shifted to the ray's point nearest the section's mid height on the
    // axis, so a far ray does not cancel in the coefficients.
    const glm::vec<3, T> centre(T(0), T(0), T(0.5 * (poly.lo.y + poly.hi.y)));
    const T tc = closest_t(o, d, centre);
    const glm::vec<3, T> c = o + tc * d;
    const int k = d.z != T(0) ? sweep_edges(poly, c, d, scratch) : level_edges(poly, c, d, scratch);
    std::sort(scratch, scratch + k, [](const PrismCrossing<T>& a, const PrismCrossing<T>& b) { return a.s < b.s; });
    int n = 0;
    PrismEnd<T> start{T(0), kPartNone, 0};
    for (int j = 0; j < k; ++j) {
        const PrismCrossing<T>& x = scratch[j];
        if (j % 2 == 0) {
            start = {x.s, edge_part(x.plus, true), x.edge};
        } else {
            emit_prism_span(out, n, tc, start, PrismEnd<T>{x.s, edge_part(x.plus, false), x.edge});
        }
    }
    return n;
}

glm::dvec3 normal_lathe(const Polygon2& poly, std::uint8_t part, std::uint32_t edge, const glm::dvec3& x) {
    if (edge >= poly.edges.size()) return {0, 0, 1};
    const glm::dvec4& e = poly.edges[edge];
    const double dr = e.z - e.x, dz = e.w - e.y;
    const double rho = std::hypot(x.x, x.y);
    const glm::dvec3 n = rho > 0 ? glm::dvec3(dz * x.x / rho, dz * x.y / rho, -dr) : glm::dvec3(0, 0, -dr);
    return part == kPartEdgeFlipped ? -n : n;
}

template int intersect_lathe<float>(const Polygon2&, const glm::vec<3, float>&, const glm::vec<3, float>&,
                                    PrismSpan<float>*, PrismCrossing<float>*);
template int intersect_lathe<double>(const Polygon2&, const glm::vec<3, double>&, const glm::vec<3, double>&,
                                     PrismSpan<double>*, PrismCrossing<double>*);

}  // namespace kerf::csg

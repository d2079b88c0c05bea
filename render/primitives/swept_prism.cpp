// A swept prism: the Prism leaf whose section map M(τ) = S(τ)·R(−θτ) is not
// a uniform positive scale (τ = (z − z0)/h; S = diag(1 + gx·τ, 1 + gy·τ);
// a top scale 0, a scale differing in x and y, a twist θ). The point at
// parameter s of the ray is inside when q(s) = M(τ(s))⁻¹·p_xy(s) lies in
// the section, so along the chord of the slab each edge (a, a + e) is
// crossed where
//     G_e(s) = cross(e, R(θτ)·W(s)) − m(s)·cross(e, a) = 0,
// G_e = m·cross(e, q − a) with W = (b·x, a·y), m = a·b (a, b the two scales;
// for a uniform scale W = p_xy, m = a, dividing out the common factor so a
// scale-0 apex is no root). m > 0 inside the slab, so G_e has the sign of
// the side of the edge's line q is on; a root counts when q is on the edge
// itself (its fraction u in [0, 1), half-open so a vertex counts once).
// Without a twist along the chord (θ = 0, or a ray parallel to the caps)
// G_e is a quadratic (linear for a uniform scale): solved in closed form.
// With a twist it is a quadratic times a rotation: roots are bracketed on a
// grid fine enough that a sign-less interval is excluded by a bound on
// |G_e''| (docs/accuracy.md, "The swept prism"), then refined.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "render/primitives/kinds.hpp"
#include "render/primitives/prism.hpp"

namespace kerf::csg {

namespace {

using V2 = glm::dvec2;

double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }
V2 rotate(V2 v, double phi) {
    const double c = std::cos(phi), s = std::sin(phi);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

struct Crossing {
    double s;
    std::uint32_t edge;
    bool plus;  // G_e decreasing: the straight prism's cross(d, edge) > 0
};

// The ray's data along the chord, in s = t − tc.
struct Sweep {
    V2 w0, w1, w2;       // W(s) = w0 + w1·s + w2·s²
    double m0, m1, m2;   // m(s)
    double phi0, omega;  // θ·τ(s) = phi0 + omega·s
    V2 w_at(double s) const { return w0 + s * (w1 + s * w2); }
    double m_at(double s) const { return m0 + s * (m1 + s * m2); }
    V2 v_at(double s) const { return rotate(w_at(s), phi0 + omega * s); }
};

// The edge's crossing function and the fraction along it at s.
struct EdgeFn {
    V2 a, e;
    double ca, ae, ee;  // cross(e, a), dot(a, e), |e|²
    explicit EdgeFn(const glm::dvec4& g) : a(g.x, g.y), e(g.z - g.x, g.w - g.y) {
        ca = cross(e, a), ae = glm::dot(a, e), ee = glm::dot(e, e);
    }
    double g(V2 v, double m) const { return cross(e, v) - m * ca; }
    bool on_edge(V2 v, double m) const {
        if (!(m > 0)) return false;
        const double u = (glm::dot(v, e) - m * ae) / (m * ee);
        return u >= 0 && u < 1;
    }
};

// Textbook even-odd point in polygon (a ray towards +x, half-open in y).
bool inside_section(const Polygon2& poly, V2 q) {
    bool odd = false;
    for (const glm::dvec4& e : poly.edges) {
        if ((e.y > q.y) == (e.w > q.y)) continue;
        if (e.x + (q.y - e.y) * (e.z - e.x) / (e.w - e.y) > q.x) odd = !odd;
    }
    return odd;
}

// Roots of A·s² + B·s + C in (lo, hi), sorted, with the sign of the slope.
int quadratic_roots(double A, double B, double C, double lo, double hi, double* r) {
    int n = 0;
    auto keep = [&](double s) { if (s > lo && s < hi) r[n++] = s; };
    if (A == 0) {
        if (B != 0) keep(-C / B);
        return n;
    }
    const double disc = B * B - 4 * A * C;
    if (disc <= 0) return 0;  // no root, or a tangency (a zero-length span)
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    double s1 = q / A, s2 = q != 0 ? C / q : -B / A;
    if (s1 > s2) std::swap(s1, s2);
    keep(s1);
    if (s2 != s1) keep(s2);
    return n;
}

// Illinois regula falsi on [l, r] with g(l), g(r) of opposite signs.
template <typename F>
double refine(F&& g, double l, double r, double gl, double gr) {
    int side = 0;
    for (int it = 0; it < 100; ++it) {
        double m = (l * gr - r * gl) / (gr - gl);
        if (!(m > l && m < r)) m = 0.5 * (l + r);
        if (!(m > l && m < r)) break;
        const double gm = g(m);
        if ((gm > 0) == (gl > 0)) {
            l = m, gl = gm;
            if (side == -1) gr *= 0.5;
            side = -1;
        } else {
            r = m, gr = gm;
            if (side == 1) gl *= 0.5;
            side = 1;
        }
        if (gm == 0) return m;
    }
    return 0.5 * (l + r);
}

}  // namespace

std::size_t swept_crossing_room(std::size_t edges, const double* p) {
    // A quadratic crosses an edge's line twice; a twist adds two per half turn.
    return edges * (2 + 2 * static_cast<std::size_t>(std::ceil(std::abs(p[4]) / std::numbers::pi)));
}

template <typename T>
int intersect_swept_prism(const Polygon2& poly, const double* p, const glm::vec<3, T>& ot, const glm::vec<3, T>& dt,
                          PrismSpan<T>* out, int room) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const glm::dvec3 o(ot), d(dt);
    const double z0 = p[0], h = p[1] - p[0], gx = p[2], gy = p[2] + p[3], theta = p[4];
    const bool uniform = p[3] == 0;
    const V2 mid = 0.5 * (poly.lo + poly.hi);
    const double tc = closest_t(o, d, glm::dvec3(mid.x, mid.y, z0 + 0.5 * h));
    const glm::dvec3 c = o + tc * d;
    // The chord of the slab in s, its caps, and τ(s) = tau0 + tau1·s.
    double sa = -inf, sb = inf;
    std::uint8_t pa = kPartNone, pb = kPartNone;
    const double tau0 = (c.z - z0) / h, tau1 = d.z / h;
    if (d.z != 0) {
        sa = (z0 - c.z) / d.z, sb = (p[1] - c.z) / d.z;
        pa = kPartBottom, pb = kPartTop;
        if (d.z < 0) std::swap(sa, sb), std::swap(pa, pb);
        if (!(sa < sb)) return 0;
    } else if (!(tau0 > 0 && tau0 < 1)) {
        return 0;
    }
    // The scales a(s) = a0 + a1·s, b(s) = b0 + b1·s and W, m.
    Sweep sw{};
    const double a0 = 1 + gx * tau0, a1 = gx * tau1, b0 = 1 + gy * tau0, b1 = gy * tau1;
    if (uniform) {
        sw.w0 = {c.x, c.y}, sw.w1 = {d.x, d.y};
        sw.m0 = a0, sw.m1 = a1;
    } else {
        sw.w0 = {b0 * c.x, a0 * c.y};
        sw.w1 = {b0 * d.x + b1 * c.x, a0 * d.y + a1 * c.y};
        sw.w2 = {b1 * d.x, a1 * d.y};
        sw.m0 = a0 * b0, sw.m1 = a0 * b1 + a1 * b0, sw.m2 = a1 * b1;
    }
    sw.phi0 = theta * tau0, sw.omega = theta * tau1;

    thread_local std::vector<Crossing> xs;
    xs.clear();
    if (sw.omega == 0) {
        // One rotation all along: G_e is a polynomial of degree ≤ 2 in s.
        for (std::uint32_t i = 0; i < poly.edges.size(); ++i) {
            const EdgeFn f(poly.edges[i]);
            const V2 er = rotate(f.e, -sw.phi0);  // cross(e, R·w) = cross(Rᵀe, w)
            const double A = cross(er, sw.w2) - sw.m2 * f.ca, B = cross(er, sw.w1) - sw.m1 * f.ca,
                         C = cross(er, sw.w0) - sw.m0 * f.ca;
            double r[2];
            const int k = quadratic_roots(A, B, C, sa, sb, r);
            for (int j = 0; j < k; ++j)
                if (f.on_edge(sw.v_at(r[j]), sw.m_at(r[j]))) xs.push_back({r[j], i, 2 * A * r[j] + B < 0});
        }
    } else {
        // A bound on |V''| over the chord (V = R·W): |W''| + 2|ω||W'| + ω²|W|.
        const double S = std::max(std::abs(sa), std::abs(sb));
        const double wmax = glm::length(sw.w0) + S * (glm::length(sw.w1) + S * glm::length(sw.w2));
        const double w1max = glm::length(sw.w1) + 2 * S * glm::length(sw.w2);
        const double om = std::abs(sw.omega);
        const double kv = 2 * glm::length(sw.w2) + 2 * om * w1max + om * om * wmax;
        // A grid of π/8 of turn per interval, shared by the edges.
        const int n = std::clamp(int(std::ceil(om * (sb - sa) / (std::numbers::pi / 8))), 2, 1 << 16);
        thread_local std::vector<V2> vs;
        thread_local std::vector<double> ms, ss;
        vs.resize(std::size_t(n) + 1), ms.resize(std::size_t(n) + 1), ss.resize(std::size_t(n) + 1);
        for (int j = 0; j <= n; ++j) {
            const double s = j == n ? sb : sa + (sb - sa) * j / n;
            ss[j] = s, vs[j] = sw.v_at(s), ms[j] = sw.m_at(s);
        }
        const double min_width = 1e-12 * (sb - sa);
        for (std::uint32_t i = 0; i < poly.edges.size(); ++i) {
            const EdgeFn f(poly.edges[i]);
            const double ke = std::sqrt(f.ee) * kv + 2 * std::abs(sw.m2 * f.ca);
            auto g = [&](double s) { return f.g(sw.v_at(s), sw.m_at(s)); };
            auto root = [&](double l, double r, double gl, double gr) {
                const double s = refine(g, l, r, gl, gr);
                if (s > sa && s < sb && f.on_edge(sw.v_at(s), sw.m_at(s))) xs.push_back({s, i, gl > 0});
            };
            // G' strays from the secant's slope by at most K·w/2 and G from
            // the chord by K·w²/8: a sign change with a steep enough secant is
            // one root, the same sign far enough from 0 none; else split.
            auto scan = [&](auto&& self, double l, double r, double gl, double gr) -> void {
                const double w = r - l;
                if ((gl > 0) != (gr > 0)) {
                    if (std::abs(gr - gl) > ke * w * w / 2 || w < min_width) return root(l, r, gl, gr);
                } else if (std::min(std::abs(gl), std::abs(gr)) > ke * w * w / 8 || w < min_width) {
                    return;
                }
                const double m = 0.5 * (l + r);
                // No double between l and r: the interval is as fine as it
                // gets (a slab 1e-29 thick, its ray's s a few ulps long; the
                // width test alone never ended there, and splitting [l, r]
                // into [l, l] and [l, r] ran forever).
                if (!(m > l && m < r)) {
                    if ((gl > 0) != (gr > 0)) root(l, r, gl, gr);
                    return;
                }
                const double gm = g(m);
                self(self, l, m, gl, gm);
                self(self, m, r, gm, gr);
            };
            double gprev = f.g(vs[0], ms[0]);
            for (int j = 0; j < n; ++j) {
                const double gnext = f.g(vs[j + 1], ms[j + 1]);
                scan(scan, ss[j], ss[j + 1], gprev, gnext);
                gprev = gnext;
            }
        }
    }
    std::sort(xs.begin(), xs.end(), [](const Crossing& x, const Crossing& y) { return x.s < y.s; });

    // Parity at the chord's start, from the midpoint of its longest piece
    // between crossings (the point farthest from any root: a start on a
    // vertex or an edge would leave the parity to rounding). A ray parallel
    // to the caps starts outside: the section is bounded.
    bool inside = false;
    if (d.z != 0) {
        double best = -1, mid = 0;
        std::size_t piece = 0;
        for (std::size_t j = 0; j <= xs.size(); ++j) {
            const double l = j == 0 ? sa : xs[j - 1].s, r = j == xs.size() ? sb : xs[j].s;
            if (r - l > best) best = r - l, mid = 0.5 * (l + r), piece = j;
        }
        const double tau = tau0 + tau1 * mid, ka = 1 + gx * tau, kb = 1 + gy * tau;
        if (ka > 0 && kb > 0) {
            const V2 pxy(c.x + mid * d.x, c.y + mid * d.y);
            inside = inside_section(poly, rotate({pxy.x / ka, pxy.y / kb}, theta * tau)) != (piece % 2 == 1);
        }
    }
    const PrismEnd<T> cap0{T(sa), pa, 0}, cap1{T(sb), pb, 0};
    PrismEnd<T> start = cap0;
    int count = 0;
    for (const Crossing& x : xs) {
        if (count == room) break;  // beyond swept_crossing_room: never seen, but never an overflow
        if (!inside)
            start = {T(x.s), edge_part(x.plus, true), x.edge};
        else
            emit_prism_span(out, count, T(tc), start, PrismEnd<T>{T(x.s), edge_part(x.plus, false), x.edge});
        inside = !inside;
    }
    if (inside && count < room) emit_prism_span(out, count, T(tc), start, cap1);
    return count;
}

// The side swept by the edge: X(τ, u) = (M(τ)·(a + u·e), z0 + h·τ); its
// normal ∂X/∂u × ∂X/∂τ = (M·e, 0) × (M'·w, h), w the point's preimage.
glm::dvec3 normal_swept_prism(const Polygon2& poly, const double* p, std::uint8_t part, std::uint32_t edge,
                              const glm::dvec3& x) {
    if (part == kPartBottom) return {0, 0, -1};
    if (part == kPartTop) return {0, 0, 1};
    if (edge >= poly.edges.size()) return {0, 0, 1};
    const double h = p[1] - p[0], gx = p[2], gy = p[2] + p[3], theta = p[4];
    const double tau = std::clamp((x.z - p[0]) / h, 0.0, 1.0);
    const double a = 1 + gx * tau, b = 1 + gy * tau;
    const glm::dvec4& g = poly.edges[edge];
    const V2 e(g.z - g.x, g.w - g.y);
    // The preimage w = R(θτ)·(x/a, y/b); at a degenerate apex, the edge's middle.
    const V2 w = a > 0 && b > 0 ? rotate({x.x / a, x.y / b}, theta * tau) : V2(0.5 * (g.x + g.z), 0.5 * (g.y + g.w));
    // M = S·R(−θτ); M' = S'·R(−θτ) − θ·S·J·R(−θτ), J the quarter turn.
    auto M = [&](V2 v) { const V2 r = rotate(v, -theta * tau); return V2(a * r.x, b * r.y); };
    const V2 rw = rotate(w, -theta * tau);
    const V2 dm = V2(gx * rw.x, gy * rw.y) - theta * V2(a * -rw.y, b * rw.x);
    const glm::dvec3 n = glm::cross(glm::dvec3(M(e), 0), glm::dvec3(dm, h));
    return part == kPartEdgeFlipped ? -n : n;
}

template int intersect_swept_prism<float>(const Polygon2&, const double*, const glm::vec<3, float>&,
                                          const glm::vec<3, float>&, PrismSpan<float>*, int);
template int intersect_swept_prism<double>(const Polygon2&, const double*, const glm::vec<3, double>&,
                                           const glm::vec<3, double>&, PrismSpan<double>*, int);

}  // namespace kerf::csg

// Torus in the XY plane: (ρ - R)² + z² < r². Work in units of R along a unit
// direction from the point of the line closest to the centre, so every
// quantity is O(1) whatever the scale, distance or ray length. The quartic
// P = (|x|² + 1 - r²)² - 4ρ² only locates the turning points that separate
// the roots and brings each root close (no sqrt); signs and final roots come
// from F = (ρ - 1)² + z² - r², which has the same sign and roots but no
// cancellation of O(1) terms for thin tori (r << R).
#include <algorithm>
#include <cmath>

#include "render/primitives/kinds.hpp"
#include "render/primitives/quartic.hpp"

namespace kerf::csg {

namespace {

template <typename T>
struct TorusLine {
    Vec3<T> q, u;  // line q + λ·u, torus R = 1, minor radius rr
    T rr2;
    // F(λ)·ρ and F'(λ)·ρ: same sign and same Newton step F/F' as F itself,
    // without a division by ρ (ρ > 0 except on the axis, far from the tube).
    // F < 0 strictly inside.
    T operator()(T lambda, T& deriv) const {
        const Vec3<T> x = q + lambda * u;
        const T rho = std::sqrt(x.x * x.x + x.y * x.y);
        const T e = rho - T(1);
        const T f = e * e + x.z * x.z - rr2;
        if (rho == T(0)) {  // on the axis: F > 0 there, keep it unscaled
            deriv = T(2) * x.z * u.z;
            return f;
        }
        deriv = T(2) * (e * (x.x * u.x + x.y * u.y) + x.z * u.z * rho);
        return f * rho;
    }
};

// The last stage of a crossing: bracketed Newton on F from x, exact.
// Near the surface, when rr <= 1/2: |F''|/2 = |ρ'² + z'² + (ρ - 1)·ρ''| <= 2
// (ρ'' <= 1/ρ) and the returned derivative is F'·ρ with ρ <= 1.5, so 4
// bounds |F''|/2·ρ for newton_in_bracket.
template <typename T>
T finish(const TorusLine<T>& line, T a, T b, bool a_inside, T x, T rr, T tol) {
    return newton_in_bracket<T>(line, a, b, a_inside, x, tol, 80, rr <= T(0.5) ? T(4) : T(0));
}

// Stages 2 and 3 of a crossing in [a, b] (a_inside: F(a) < 0, F(b) >= 0;
// else the reverse) from the first guess x: Newton on the polynomial P
// until its steps predict ~1e-10 (no sqrt; P loses digits to cancellation
// for thin tori, so only to start the last stage), then bracketed Newton on
// F, which is exact; usually one step suffices. prev: the step before x's
// (Newton's error after a step is about step³/prev²).
template <typename T>
T polish(const TorusLine<T>& line, const T c[5], T a, T b, bool a_inside, T x, T prev, T rr, T tol) {
    const T coarse = std::sqrt(std::numeric_limits<T>::epsilon()) * T(0.01);
    for (int it = 0; it < 8; ++it) {
        // P and P' by Estrin's scheme: half the dependent chain of Horner's,
        // and this loop is one chain.
        const T x2 = x * x;
        const T px = (c[0] + c[1] * x) + x2 * ((c[2] + c[3] * x) + c[4] * x2);
        const T dpx = (c[1] + T(2) * c[2] * x) + x2 * (T(3) * c[3] + T(4) * c[4] * x);
        const T step = px / dpx;
        const T next = x - step;
        if (!(next > a && next < b)) break;  // P's rounding or a far start: F takes over
        x = next;
        const T as = std::abs(step);
        if (as * as * as <= coarse * std::max(T(1), std::abs(x)) * prev * prev) break;
        prev = as;
    }
    return finish(line, a, b, a_inside, x, rr, tol);
}

// The crossing in the piece [a, b] of the chord, where F changes sign once;
// the inside end t (F(t) < 0) is at or near a minimum of P, or an end of the
// window. The first guess is a quadratic model P(t + δ) ≈ P(t) + P'(t)·δ +
// A·δ² (A: P''(t)/2, or the curvature of the chord to the outside end if
// larger, which keeps the model's root inside the piece); for a thin tube F
// is nearly quadratic there, so this is already close.
template <typename T>
T crossing(const TorusLine<T>& line, const T c[5], T a, T b, bool a_inside, T rr, T tol) {
    const T t = a_inside ? a : b, e = a_inside ? b : a, w = e - t;
    T dp, hp2, dummy;
    const T p = poly_taylor2<T, 4>(c, t, dp, hp2);
    const T pe = poly_eval<T, 4>(c, e, dummy);
    T x = T(0.5) * (a + b);
    if (p < T(0) && pe > T(0)) {
        const T A = std::max(hp2, (pe - p - dp * w) / (w * w));
        // The model's root on e's side, in the form without cancellation.
        const T sdp = w > T(0) ? dp : -dp;
        const T xq = t + std::copysign(T(-2) * p / (std::sqrt(dp * dp - T(4) * A * p) + sdp), w);
        if (xq > a && xq < b) x = xq;
    }
    return polish(line, c, a, b, a_inside, x, b - a, rr, tol);
}

// F and its first two derivatives at λ, for a point off the axis (ρ > 0):
// F' = 2·((ρ - 1)·ρ' + z·u_z), F'' = 2·(uu - ρ''), ρ'' = K/ρ³ (see the
// convex case in intersect_torus). f is the value TorusLine scales by ρ:
// the same sign.
template <typename T>
struct FTaylor {
    T f, d1, d2;
};

template <typename T>
FTaylor<T> f_taylor(const TorusLine<T>& line, T K, T uu, T lambda) {
    const Vec3<T> x = line.q + lambda * line.u;
    const T rho = std::sqrt(x.x * x.x + x.y * x.y);
    const T inv = T(1) / rho;
    const T e = rho - T(1);
    return {e * e + x.z * x.z - line.rr2, T(2) * (e * (x.x * line.u.x + x.y * line.u.y) * inv + x.z * line.u.z),
            T(2) * (uu - K * inv * inv * inv)};
}

// The crossing in [a, b] where F is convex, from the quadratic model of F
// itself at the inside end (F, F', F'' exact there, and known from the
// window's cut): a straight tube would make it exact, the ring's curvature
// leaves ~1e-3·R (the median on the grooved sphere, a few times closer than
// P's model). F'' > 0, so with F(t) < 0 the model has one root on the way out.
template <typename T>
T crossing_convex(const TorusLine<T>& line, const T c[5], const FTaylor<T>& at, T a, T b, bool a_inside, T rr,
                  T tol) {
    const T t = a_inside ? a : b;
    const T g = a_inside ? at.d1 : -at.d1, h = T(0.5) * at.d2;  // along the way out
    const T sq = std::sqrt(g * g - T(4) * h * at.f);
    // The root of f + g·s + h·s² with s > 0, in the form without cancellation.
    const T s = g > T(0) ? T(-2) * at.f / (g + sq) : (sq - g) / (T(2) * h);
    const T x = a_inside ? t + s : t - s;
    if (!(x > a && x < b)) return polish(line, c, a, b, a_inside, T(0.5) * (a + b), b - a, rr, tol);
    // One Halley step on P (cubic convergence: the model's ~1e-3 becomes
    // ~1e-6…1e-9), then Newton on F; cheaper than Newton on P to 1e-10.
    const T x2 = x * x;
    const T px = (c[0] + c[1] * x) + x2 * ((c[2] + c[3] * x) + c[4] * x2);
    const T dpx = (c[1] + T(2) * c[2] * x) + x2 * (T(3) * c[3] + T(4) * c[4] * x);
    const T hpx = (c[2] + T(3) * c[3] * x) + T(6) * c[4] * x2;  // P''/2
    const T next = x - px * dpx / (dpx * dpx - px * hpx);
    if (!(next > a && next < b)) return polish(line, c, a, b, a_inside, x, s, rr, tol);
    return finish(line, a, b, a_inside, next, rr, tol);
}

}  // namespace

template <typename T>
int intersect_torus(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out, T wa, T wb) {
    constexpr T eps = std::numeric_limits<T>::epsilon();
    const T R = T(p[0]);
    const T rr = T(p[1] / p[0]);
    const T dd = glm::dot(d, d);
    const T tc = -glm::dot(o, d) / dd;
    const Vec3<T> q = (o + tc * d) / R;
    // Cheap rejection: bounding sphere (radius 1 + rr), then the slab |z| < rr.
    const T outer = T(1) + rr;
    const T q2 = glm::dot(q, q);
    if (q2 >= outer * outer) return 0;
    const T len = std::sqrt(dd);
    const Vec3<T> u = d / len;
    T half = std::sqrt((outer - std::sqrt(q2)) * (outer + std::sqrt(q2)));
    T lo = -half, hi = half;
    if (u.z != T(0)) {
        T za = (-rr - q.z) / u.z, zb = (rr - q.z) / u.z;
        if (za > zb) { const T t = za; za = zb; zb = t; }
        lo = std::max(lo, za);
        hi = std::min(hi, zb);
    } else if (!(std::abs(q.z) < rr)) {
        return 0;
    }
    if (!(lo < hi)) return 0;
    // Ring test: the tube lies in (1 - rr)² <= ρ² <= (1 + rr)². ρ²(λ) is a
    // convex parabola, so its largest value on [lo, hi] is at an end and its
    // smallest at the vertex or an end. A chord that stays in the hole (a ray
    // looking down through the ring) or outside the ring's rim misses, and
    // costs no quartic. Cut only with a margin, so grazing rays are solved.
    const T alpha = u.x * u.x + u.y * u.y, beta = q.x * u.x + q.y * u.y, gamma = q.x * q.x + q.y * q.y;
    const T vertex_line = alpha > T(0) ? -beta / alpha : T(0);  // where ρ² is least along the line
    {
        const T r_lo = alpha * lo * lo + T(2) * beta * lo + gamma;
        const T r_hi = alpha * hi * hi + T(2) * beta * hi + gamma;
        const T slack = T(64) * eps;
        if (rr < T(1) && std::max(r_lo, r_hi) < (T(1) - rr) * (T(1) - rr) - slack) return 0;
        const T vertex = alpha > T(0) ? std::clamp(vertex_line, lo, hi) : lo;
        const T r_min = std::min({r_lo, r_hi, alpha * vertex * vertex + T(2) * beta * vertex + gamma});
        if (r_min > (T(1) + rr) * (T(1) + rr) + slack) return 0;
    }
    // Widen by a few ulps so the ends are surely outside the torus (they are
    // on its bounding surfaces): the sign walk below assumes they are.
    const T margin = T(8) * eps * (T(1) + half);
    lo -= margin;
    hi += margin;

    const TorusLine<T> line{q, u, rr * rr};
    const T scale = R / len;  // λ -> t
    // Only the window [wlo, whi] needs exact roots (spans' contract): the
    // chord is clipped to it before any turn or root is looked for, so
    // rays that start inside a tube or leave the window inside one (most
    // rays into a groove) solve only what they see. A cut end takes its
    // sign from F; a span through it is reported from or to the window end
    // (outside the part the caller reads: it padded the window).
    const T wlo = (wa - tc) / scale, whi = (wb - tc) / scale;
    // F'' needs K = αγ - β² = (q × u)_z², without αγ - β²'s cancellation.
    const T cross = q.x * u.y - q.y * u.x;
    const T K = cross * cross;
    const T uu = glm::dot(u, u);
    // A cut end's F, F' and F'' (on the axis only F means anything; the
    // derivatives are read only where F is convex, which keeps off the axis).
    FTaylor<T> at_lo{T(1), T(0), T(0)}, at_hi{T(1), T(0), T(0)};  // the chord's own ends are outside
    if (wlo > lo) {
        if (!(wlo < hi)) return 0;
        lo = wlo;
        at_lo = f_taylor(line, K, uu, lo);
    }
    if (whi < hi) {
        if (!(whi > lo)) return 0;
        hi = whi;
        at_hi = f_taylor(line, K, uu, hi);
    }
    const T f_lo = at_lo.f, f_hi = at_hi.f;
    T dummy;

    const T b = glm::dot(q, u);
    const T k = q2 + T(1) - rr * rr;
    const T c[5] = {k * k - T(4) * gamma, T(4) * b * k - T(8) * beta,
                    T(4) * b * b + T(2) * uu * k - T(4) * alpha, T(4) * uu * b, uu * uu};
    const T tol = T(2) * eps;
    // A window that starts or ends inside the tube (a ray into a groove, a
    // shadow ray leaving one) where F is convex: F crosses zero at most once
    // after a negative end, so there are no turns to find: one crossing or
    // none. F = |x|² + 1 - rr² - 2ρ, so F'' = 2·(uu - ρ'') with ρ'' = K/ρ³,
    // K = αγ - β² = (q × u)_z² (no cancellation): F is convex where
    // uu·ρ³ > K. ρ² = α·(λ - λv)² + K/α is least at the window's point
    // nearest the vertex λv (a sum of non-negative terms); both sides get
    // slack for their rounding. Fails only near the axis (ρ'' large) or for
    // lines nearly in the ring's plane passing inside the ring (α ≈ 1, h < α).
    if (f_lo < T(0) || f_hi < T(0)) {
        T rho2_min = gamma;
        if (alpha > T(0)) {
            const T v = std::clamp(vertex_line, lo, hi) - vertex_line;
            rho2_min = alpha * v * v + K / alpha;
        }
        const T m = rho2_min - T(64) * eps * outer * outer;
        if (m > T(0) && uu * uu * (m * m * m) > K * K * (T(1) + T(64) * eps)) {
            int n = 0;
            const bool lo_in = f_lo < T(0);
            T s0 = lo, s1 = hi;
            if (!(lo_in && f_hi < T(0))) {
                const T root = lo_in ? crossing_convex(line, c, at_lo, lo, hi, true, rr, tol)
                                     : crossing_convex(line, c, at_hi, lo, hi, false, rr, tol);
                (lo_in ? s1 : s0) = root;
            }
            emit_span(out, n, tc, s0 * scale, s1 * scale, kPartSide, kPartSide);
            return n;
        }
    }
    Turn<T> turns[3];
    const int nturn = quartic_turns(c, lo, hi, turns);

    // Walk the monotone pieces; each sign change of F is one crossing.
    // F == 0 counts as outside (the surface is not inside).
    bool inside = f_lo < T(0);
    T enter = lo;
    T f_prev = f_lo;
    T x_prev = lo;
    int n = 0;
    for (int i = 0; i <= nturn; ++i) {
        T x = hi, f = f_hi;
        if (i < nturn) {
            // A turn's first point separates the pieces if P there has the
            // sign of the extremum; F has P's sign (P = F·((ρ + 1)² + z² - rr²)
            // and rr < 1). It must be clear of F's rounding (about 4·rr·eps:
            // the point's rounding times |∇F| = 2·rr) so that undecidable
            // grazes are still decided at the extremum. Otherwise (a near
            // miss or a graze) only the extremum itself can tell.
            Turn<T>& turn = turns[i];
            f = line(turn.x, dummy);
            const T clear = T(16) * eps * rr;
            if (!(rr < T(1)) || (turn.min ? !(f < -clear) : !(f > clear))) {
                refine_turn(c, turn, T(4) * eps);
                f = line(turn.x, dummy);
            }
            x = turn.x;
        }
        const bool in_b = f < T(0);
        if (in_b != inside) {
            const T root = crossing(line, c, x_prev, x, f_prev < T(0), rr, tol);
            if (in_b) {
                enter = root;
            } else if (n < kMaxSpans) {
                emit_span(out, n, tc, enter * scale, root * scale, kPartSide, kPartSide);
            }
            inside = in_b;
        }
        f_prev = f;
        x_prev = x;
    }
    // Still inside at the window's far end: the span runs on beyond it.
    if (inside && n < kMaxSpans) emit_span(out, n, tc, enter * scale, hi * scale, kPartSide, kPartSide);
    return n;
}

glm::dvec3 normal_torus(const double* p, const glm::dvec3& x, std::uint8_t) {
    // From the nearest point of the core circle out to x.
    const double rho = std::sqrt(x.x * x.x + x.y * x.y);
    if (rho == 0) return {0, 0, x.z >= 0 ? 1.0 : -1.0};
    const double s = p[0] / rho;
    return {x.x - s * x.x, x.y - s * x.y, x.z};
}

template int intersect_torus<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*, float, float);
template int intersect_torus<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*, double,
                                     double);

}  // namespace kerf::csg

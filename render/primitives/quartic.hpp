// Root isolation for a quartic on a bounded interval, after Yuksel, "High-
// performance polynomial root finding for graphics" (HPG 2022): the roots of
// the derivative split the interval into pieces where the polynomial is
// monotone, so each piece holds at most one root and a bracketed Newton
// iteration finds it. No closed-form Ferrari/Cardano step, whose cancellation
// is what ruins thin tori; no complex arithmetic; cost bounded by the interval.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "render/primitives/quadratic.hpp"

namespace kerf::csg {

// c[0] + c[1]·x + ... + c[N]·x^N and its derivative (Horner), unrolled at
// compile time: -O2 keeps the loop, whose overhead is most of a cubic's cost.
template <typename T, int N>
inline T poly_eval(const T* c, T x, T& deriv) {
    T v = c[N], dv = T(0);
    [&]<int... I>(std::integer_sequence<int, I...>) {
        ((dv = dv * x + v, v = v * x + c[N - 1 - I]), ...);
    }(std::make_integer_sequence<int, N>{});
    deriv = dv;
    return v;
}

// The same with half the second derivative as well: the Taylor coefficients
// of degree 0, 1 and 2 at x.
template <typename T, int N>
inline T poly_taylor2(const T* c, T x, T& deriv, T& half_second) {
    T v = c[N], dv = T(0), hv = T(0);
    [&]<int... I>(std::integer_sequence<int, I...>) {
        ((hv = hv * x + dv, dv = dv * x + v, v = v * x + c[N - 1 - I]), ...);
    }(std::make_integer_sequence<int, N>{});
    deriv = dv;
    half_second = hv;
    return v;
}

// A root of f in [a, b], where f(a) < 0 exactly when a_negative and f(b) has
// the other sign: Newton from x (in (a, b)), falling back to bisection
// whenever a step leaves the shrinking bracket. f(x, deriv) returns f and sets
// f'. Stops once a step is below tol·max(1, |x|) (tol: a few eps, relative,
// so Newton cannot cycle between neighbouring floats until max_iter).
// Returns the stepped point x - step, not x, once the step is that small.
// curv > 0: a bound on |f''|/2·|deriv|/|f'| near the root (f may return a
// scaled derivative `deriv`). Newton's error after a step is then at most
// about curv·step²/|deriv|; once that is below the stop rule, the step is
// taken without another evaluation to confirm it.
template <typename T, typename F>
inline T newton_in_bracket(F&& f, T a, T b, bool a_negative, T x, T tol, int max_iter, T curv = T(0)) {
    for (int it = 0; it < max_iter; ++it) {
        T df;
        const T fx = f(x, df);
        if (fx == T(0)) return x;
        if ((fx < T(0)) == a_negative) a = x; else b = x;
        const T step = fx / df;
        // Converged: checked before the bracket test, since at the root the
        // rounding noise in f may point a tiny step just outside the bracket.
        const T stop = tol * std::max(T(1), std::abs(x));
        T next = x - step;
        const bool in_bracket = next > a && next < b;
        if (std::abs(step) <= stop) return in_bracket ? next : x;
        if (in_bracket && curv > T(0) && curv * step * step <= stop * std::abs(df)) return next;
        if (!in_bracket) next = T(0.5) * (a + b);  // also catches df == 0 / NaN
        if (!(a < next && next < b)) return x;  // the bracket has collapsed
        x = next;
    }
    return x;
}

// A turning point of the quartic P, isolated in a piece (a, b) of the
// interval where P' is monotone and changes sign once. x is only a point of
// (a, b) until refine_turn() makes it the turning point: P is monotone
// between any point of the piece and the turning point, so for sign walks x
// already separates the monotone pieces of P whenever P(x) has the sign of
// the extremum (negative at a minimum, positive at a maximum).
template <typename T>
struct Turn {
    T x, a, b;  // a == b: x is exact
    bool min;   // P' goes from negative to positive: P has a minimum
};

// The turns of the quartic c[0..4] in (lo, hi), sorted. Returns the count.
template <typename T>
inline int quartic_turns(const T c[5], T lo, T hi, Turn<T> out[3]) {
    const T d1[4] = {c[1], T(2) * c[2], T(3) * c[3], T(4) * c[4]};  // P'
    // Turning points of P' itself: roots of P'' = 12c4·x² + 6c3·x + 2c2.
    T cut[4] = {lo, hi, hi, hi};
    int ncut = 1;
    const T qa = T(12) * c[4], qhb = T(3) * c[3], qc = T(2) * c[2];
    // Kahan's compensated discriminant (a dozen products without an fma)
    // only where the plain one cancels: above (b² + |ac|)/8 the plain one is
    // within 5 ulps, and the cuts need no better.
    const T b2 = qhb * qhb, ac = qa * qc;
    T disc = b2 - ac;
    if (!(std::abs(disc) > T(0.125) * (b2 + std::abs(ac)))) disc = T(discriminant(qhb, qa, qc));
    if (disc > T(0) && qa != T(0)) {
        const T q = -(qhb + std::copysign(std::sqrt(disc), qhb));
        T x1 = q / qa, x2 = qc / q;
        if (x1 > x2) { const T t = x1; x1 = x2; x2 = t; }
        if (x1 > lo && x1 < hi) cut[ncut++] = x1;
        if (x2 > lo && x2 < hi) cut[ncut++] = x2;
    }
    cut[ncut++] = hi;
    int n = 0;
    T da;
    T va = poly_eval<T, 3>(d1, cut[0], da);
    for (int i = 0; i + 1 < ncut; ++i) {
        T db;
        const T vb = poly_eval<T, 3>(d1, cut[i + 1], db);
        if ((va < T(0)) != (vb < T(0)) && va != T(0) && vb != T(0)) {
            const T a = cut[i], b = cut[i + 1];
            // x: inverse cubic Hermite interpolation of x(P') through both
            // ends (values and slopes), else the secant point.
            const T h = vb - va, s = -va / h;
            const T h10 = s * (s - T(1)) * (s - T(1)), h11 = s * s * (s - T(1));
            const T h01 = s * s * (T(3) - T(2) * s);
            T x = a + h01 * (b - a) + h * (h10 / da + h11 / db);
            if (!(x > a && x < b)) x = a + s * (b - a);
            if (!(x > a && x < b)) x = T(0.5) * (a + b);
            out[n++] = Turn<T>{x, a, b, va < T(0)};
        } else if (vb == T(0) && i + 2 < ncut) {
            const T x = cut[i + 1];  // an exact turning point at a cut
            out[n++] = Turn<T>{x, x, x, va < T(0)};
        }
        va = vb;
        da = db;
    }
    return n;
}

// The turning point itself: Newton on P' in the turn's piece.
template <typename T>
inline void refine_turn(const T c[5], Turn<T>& turn, T tol) {
    if (!(turn.a < turn.b)) return;
    const T d1[4] = {c[1], T(2) * c[2], T(3) * c[3], T(4) * c[4]};
    auto fd = [&](T x, T& df) { return poly_eval<T, 3>(d1, x, df); };
    turn.x = newton_in_bracket<T>(fd, turn.a, turn.b, turn.min, turn.x, tol, 60);
}

}  // namespace kerf::csg

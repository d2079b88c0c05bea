// Where a quadratic along a line is negative: the interior of every quadric
// primitive (sphere, cylinder/cone side, paraboloid, hyperboloid) along a ray.
// Written for accuracy rather than brevity: the discriminant uses Kahan's
// fma trick (its cancellation is what decides grazing rays), and the roots use
// the cancellation-free pair q/a, c/q instead of (-b ± sqrt(disc)) / 2a.
#pragma once
#include <cmath>
#include <limits>

namespace kerf::csg {

template <typename T>
struct Interval {
    T lo, hi;
};

// a·b = p + e exactly (Dekker's product; fma where the target has it —
// the default x86-64 target does not, and libm's software fma is slow).
inline void two_product(double a, double b, double& p, double& e) {
    p = a * b;
#if defined(FP_FAST_FMA)
    e = std::fma(a, b, -p);
#else
    constexpr double split = 134217729.0;  // 2^27 + 1
    const double ca = split * a, cb = split * b;
    const double ahi = ca - (ca - a), alo = a - ahi;
    const double bhi = cb - (cb - b), blo = b - bhi;
    e = ((ahi * bhi - p) + ahi * blo + alo * bhi) + alo * blo;
#endif
}

// b² - a·c with the rounding error of both products compensated (Kahan,
// "On the cost of floating-point computation without extra-precise
// arithmetic"): accurate to a few ulps unless the result itself is tiny.
inline double discriminant(double b, double a, double c) {
    double pb, eb, pac, eac;
    two_product(b, b, pb, eb);
    two_product(a, c, pac, eac);
    return (pb - pac) + (eb - eac);
}

// Float: the products of two floats are exact in double, so one rounding.
inline float discriminant(float b, float a, float c) {
    return float(double(b) * double(b) - double(a) * double(c));
}

// Intervals of s where a·s² + 2·hb·s + c < 0 (the open interior; note the half
// linear coefficient). Returns 0, 1 or 2 sorted disjoint intervals; ends may
// be ±inf. Degenerate rule: a double root touching 0 from above (a > 0,
// disc == 0) is no interval; touching from below (a < 0, disc == 0) leaves
// the whole line (a zero-length gap is no gap).
template <typename T>
inline int quadric_negative(T a, T hb, T c, Interval<T> out[2]) {
    constexpr T inf = std::numeric_limits<T>::infinity();
    if (a == T(0)) {  // linear (or constant) along the line
        if (hb == T(0)) {
            if (c < T(0)) { out[0] = {-inf, inf}; return 1; }
            return 0;
        }
        const T s = -c / (T(2) * hb);
        out[0] = hb > T(0) ? Interval<T>{-inf, s} : Interval<T>{s, inf};
        return 1;
    }
    const T disc = discriminant(hb, a, c);
    if (disc <= T(0)) {
        if (a > T(0)) return 0;
        out[0] = {-inf, inf};
        return 1;
    }
    const T q = -(hb + std::copysign(std::sqrt(disc), hb));
    T s1 = q / a, s2 = c / q;  // q != 0: disc > 0
    if (s1 > s2) { const T tmp = s1; s1 = s2; s2 = tmp; }
    if (a > T(0)) {
        if (!(s1 < s2)) return 0;
        out[0] = {s1, s2};
        return 1;
    }
    if (!(s1 < s2)) { out[0] = {-inf, inf}; return 1; }  // zero-length gap
    out[0] = {-inf, s1};
    out[1] = {s2, inf};
    return 2;
}

}  // namespace kerf::csg

// Sphere of radius r at the origin: |x|² < r².
// Solved around the point c0 of the line closest to the centre: a hit needs
// c = |c0|² - r² < 0, and then the discriminant hb² - a·c is a sum of two
// non-negative terms, so it needs no compensation (unlike the general
// quadric in quadratic.hpp); the roots still use the cancellation-free pair.
// solve_sphere is in a header so that the bare-sphere crowds' loops
// (render/tracer/bare_spheres.hpp) solve it inline; sphere.cpp's
// intersect_sphere (kinds.hpp, for intersect_leaf) calls it. The same
// operations in the same order give the same bits as long as the compiler
// contracts no multiply-add (x86-64's default; GCC's -ffp-contract=fast on
// targets with FMA would need -ffp-contract=off).
#pragma once
#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "render/primitives/kinds.hpp"

namespace kerf::csg {

namespace sphere_detail {

// lo, hi = r0, r1 swapped if r0 > r1 (for distinct, non-NaN roots). In double by SSE2's
// minsd and maxsd, which GCC would otherwise turn back into the branch.
template <typename T>
inline void ordered(T r0, T r1, T& lo, T& hi) {
    lo = std::min(r0, r1);
    hi = std::max(r1, r0);
}
#if defined(__SSE2__)
template <>
inline void ordered(double r0, double r1, double& lo, double& hi) {
    const __m128d x = _mm_set_sd(r0), y = _mm_set_sd(r1);
    lo = _mm_cvtsd_f64(_mm_min_sd(x, y));  // r0 < r1 ? r0 : r1
    hi = _mm_cvtsd_f64(_mm_max_sd(y, x));  // r1 > r0 ? r1 : r0
}
#endif

}  // namespace sphere_detail

template <typename T>
[[gnu::always_inline]] inline int solve_sphere(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    const T r = T(p[0]);
    const T a = glm::dot(d, d);
    const T tc = -glm::dot(o, d) / a;
    const Vec3<T> c0 = o + tc * d;
    const T c = glm::dot(c0, c0) - r * r;
    if (!(c < T(0))) return 0;  // cheap rejection: the line misses (or only touches)
    const T hb = glm::dot(c0, d);
    const T q = -(hb + std::copysign(std::sqrt(hb * hb - a * c), hb));
    const T r0 = q / a, r1 = c / q;
    // The roots in order: min and max are the swap `if (r0 > r1)` made,
    // without its branch. They differ from it only for equal roots (which
    // may come back swapped) or a NaN (|d|² overflowing): emit_span's
    // !(t0 < t1) drops both alike. hb's sign, which decides the order, is a
    // coin toss for rays that hit (c0 is nearly perpendicular to d), and
    // the branch waited on both divisions to find out it had guessed wrong.
    T s0, s1;
    sphere_detail::ordered(r0, r1, s0, s1);
    int n = 0;
    emit_span(out, n, tc, s0, s1, kPartSide, kPartSide);
    return n;
}

}  // namespace kerf::csg

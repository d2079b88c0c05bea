// Per-primitive ray intervals and normals behind intersect_leaf() /
// object_normal() (primitives.cpp dispatches on Leaf::kind with a switch).
// Every function gets the leaf's canonical parameters (see PrimKind) and an
// object-space ray o + t·d with d not normalised; each lives in its own
// prim_<kind>.cpp with explicit float and double instantiations.
#pragma once
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "render/primitives/primitives.hpp"
#include "render/primitives/quadratic.hpp"

namespace kerf::csg {

template <typename T>
using Vec3 = glm::vec<3, T>;

// Surface part ids (Span::part0/part1, object_normal's `part`).
constexpr std::uint8_t kPartSide = 0;    // curved surface (sphere, torus, sides), plane
constexpr std::uint8_t kPartBottom = 1;  // cap at the low z end
constexpr std::uint8_t kPartTop = 2;     // cap at the high z end
// Box faces: axis (0 x, 1 y, 2 z) for the min face, axis + 3 for the max face.
constexpr std::uint8_t kPartNone = 255;  // infinite span end (half-spaces)

template <typename T> int intersect_sphere(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out);
template <typename T> int intersect_box(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out);
template <typename T> int intersect_cylinder(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out);
template <typename T>
int intersect_torus(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out, T wa, T wb);
template <typename T> int intersect_plane(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out);
template <typename T> int intersect_paraboloid(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out);
template <typename T> int intersect_hyperboloid(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out);

glm::dvec3 normal_sphere(const double* p, const glm::dvec3& x, std::uint8_t part);
glm::dvec3 normal_box(const double* p, const glm::dvec3& x, std::uint8_t part);
glm::dvec3 normal_cylinder(const double* p, const glm::dvec3& x, std::uint8_t part);
glm::dvec3 normal_torus(const double* p, const glm::dvec3& x, std::uint8_t part);
glm::dvec3 normal_plane(const double* p, const glm::dvec3& x, std::uint8_t part);
glm::dvec3 normal_paraboloid(const double* p, const glm::dvec3& x, std::uint8_t part);
glm::dvec3 normal_hyperboloid(const double* p, const glm::dvec3& x, std::uint8_t part);

// The parameter of the point of the line closest to `centre`. Solving around
// that point instead of around o keeps far rays (|o| >> object size) from
// cancelling catastrophically in the quadratic's coefficients.
template <typename T>
inline T closest_t(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& centre) {
    return -glm::dot(o - centre, d) / glm::dot(d, d);
}

// Cheap rejection before the quadratic: the line's point closest to `centre`
// lies outside the ball of radius² r2 around it (with a few ulps to spare, so
// a line grazing a rim that touches the ball is still solved exactly).
template <typename T>
inline bool misses_ball(const Vec3<T>& closest, const Vec3<T>& centre, T r2) {
    const Vec3<T> v = closest - centre;
    return glm::dot(v, v) > r2 * (T(1) + T(16) * std::numeric_limits<T>::epsilon());
}

// Appends the span [tc + s0, tc + s1] (spans come in increasing order) if it
// keeps a positive length once shifted back; a gap that rounds to nothing
// merges it with the previous span (degenerate rule, docs/accuracy.md).
template <typename T>
inline void emit_span(Span<T>* out, int& n, T tc, T s0, T s1, std::uint8_t p0, std::uint8_t p1) {
    const T t0 = tc + s0, t1 = tc + s1;
    if (!(t0 < t1)) return;
    if (n > 0 && !(out[n - 1].t1 < t0)) {
        out[n - 1].t1 = t1;
        out[n - 1].part1 = p1;
        return;
    }
    out[n++] = Span<T>{t0, t1, p0, p1};
}

// Interior of {q(s) < 0} ∩ {zlo < z(s) < zhi} for z(s) = oz + s·dz: a quadric
// side between two caps. Ties between a cap and the side go to the cap, so a
// ray through the rim reports the cap (degenerate rule, docs/accuracy.md).
template <typename T>
inline int quadric_between_caps(T a, T hb, T c, T oz, T dz, T zlo, T zhi, T tc, Span<T>* out) {
    constexpr T inf = std::numeric_limits<T>::infinity();
    T sa = -inf, sb = inf;
    std::uint8_t pa = kPartNone, pb = kPartNone;
    if (dz != T(0)) {
        sa = (zlo - oz) / dz;
        sb = (zhi - oz) / dz;
        pa = kPartBottom;
        pb = kPartTop;
        if (dz < T(0)) {
            const T tmp = sa; sa = sb; sb = tmp;
            pa = kPartTop;
            pb = kPartBottom;
        }
        if (!(sa < sb)) return 0;
    } else if (!(zlo < oz && oz < zhi)) {
        return 0;  // parallel to the caps and not strictly between them
    }
    Interval<T> iv[2];
    const int k = quadric_negative(a, hb, c, iv);
    int n = 0;
    for (int i = 0; i < k; ++i) {
        const bool cap0 = sa >= iv[i].lo, cap1 = sb <= iv[i].hi;
        const T s0 = cap0 ? sa : iv[i].lo, s1 = cap1 ? sb : iv[i].hi;
        if (s0 < s1) emit_span(out, n, tc, s0, s1, cap0 ? pa : kPartSide, cap1 ? pb : kPartSide);
    }
    return n;
}

}  // namespace kerf::csg

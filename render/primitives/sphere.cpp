// Sphere of radius r at the origin: |x|² < r².
// Solved around the point c0 of the line closest to the centre: a hit needs
// c = |c0|² - r² < 0, and then the discriminant hb² - a·c is a sum of two
// non-negative terms, so it needs no compensation (unlike the general
// quadric in quadratic.hpp); the roots still use the cancellation-free pair.
#include <cmath>

#include "render/primitives/kinds.hpp"

namespace kerf::csg {

template <typename T>
int intersect_sphere(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    const T r = T(p[0]);
    const T a = glm::dot(d, d);
    const T tc = -glm::dot(o, d) / a;
    const Vec3<T> c0 = o + tc * d;
    const T c = glm::dot(c0, c0) - r * r;
    if (!(c < T(0))) return 0;  // cheap rejection: the line misses (or only touches)
    const T hb = glm::dot(c0, d);
    const T q = -(hb + std::copysign(std::sqrt(hb * hb - a * c), hb));
    T s0 = q / a, s1 = c / q;
    if (s0 > s1) { const T tmp = s0; s0 = s1; s1 = tmp; }
    int n = 0;
    emit_span(out, n, tc, s0, s1, kPartSide, kPartSide);
    return n;
}

void intersect_sphere_rays(const Leaf& leaf, int n, const glm::dvec3* o, const glm::dvec3* d, Span<double>* out,
                           int* count) {
    for (int k = 0; k < n; ++k) count[k] = intersect_sphere<double>(leaf.p, o[k], d[k], out + k * kMaxSpans);
}

glm::dvec3 normal_sphere(const double*, const glm::dvec3& x, std::uint8_t) { return x; }

template int intersect_sphere<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*);
template int intersect_sphere<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*);

}  // namespace kerf::csg

// Sphere of radius r at the origin: |x|² < r².
#include <cmath>

#include "render/prim_kinds.hpp"

namespace kerf::csg {

template <typename T>
int intersect_sphere(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    const T r = T(p[0]);
    const T tc = closest_t(o, d, Vec3<T>(0));
    const Vec3<T> c0 = o + tc * d;  // closest point: its distance decides hit or miss
    const T c = std::fma(-r, r, glm::dot(c0, c0));
    if (c >= T(0)) return 0;        // cheap rejection: the line misses (or touches)
    Interval<T> iv[2];
    if (quadric_negative(glm::dot(d, d), glm::dot(c0, d), c, iv) != 1) return 0;
    int n = 0;
    emit_span(out, n, tc, iv[0].lo, iv[0].hi, kPartSide, kPartSide);
    return n;
}

glm::dvec3 normal_sphere(const double*, const glm::dvec3& x, std::uint8_t) { return x; }

template int intersect_sphere<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*);
template int intersect_sphere<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*);

}  // namespace kerf::csg

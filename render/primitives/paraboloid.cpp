// Paraboloid k·ρ² < z < h with k = h / r² (apex at the origin, cap at z = h).
// A ray parallel to the axis makes the quadratic linear (handled by
// quadric_negative's a == 0 case).
#include <limits>

#include "render/primitives/kinds.hpp"

namespace kerf::csg {

template <typename T>
int intersect_paraboloid(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    const T h = T(p[0]);
    const T k = T(p[0] / (p[1] * p[1]));
    const Vec3<T> centre(0, 0, h / T(2));
    const T tc = closest_t(o, d, centre);
    const Vec3<T> c0 = o + tc * d;
    if (misses_ball(c0, centre, T(0.25 * p[0] * p[0] + p[1] * p[1]))) return 0;  // the rim lies on it
    const T a = k * (d.x * d.x + d.y * d.y);
    const T hb = k * (c0.x * d.x + c0.y * d.y) - d.z / T(2);
    const T c = k * (c0.x * c0.x + c0.y * c0.y) - c0.z;
    // Only the top cap: k·ρ² < z already implies z > 0.
    return quadric_between_caps(a, hb, c, c0.z, d.z, -std::numeric_limits<T>::infinity(), h, tc, out);
}

glm::dvec3 normal_paraboloid(const double* p, const glm::dvec3& x, std::uint8_t part) {
    if (part == kPartTop) return {0, 0, 1};
    const double k = p[0] / (p[1] * p[1]);
    return {2 * k * x.x, 2 * k * x.y, -1};
}

template int intersect_paraboloid<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*);
template int intersect_paraboloid<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*);

}  // namespace kerf::csg

// Capped cylinder, frustum or cone along z: z0 < z < z1 and
// ρ < r(z) = r0 + m·(z - z0). The side is the quadric ρ² = r(z)²; its mirror
// nappe (r(z) < 0) lies beyond the apex, outside the caps, so clipping the
// quadric's interior by the slab gives exactly the solid.
#include <algorithm>
#include <cmath>

#include "render/primitives/kinds.hpp"

namespace kerf::csg {

template <typename T>
int intersect_cylinder(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    const T z0 = T(p[0]), z1 = T(p[1]), r0 = T(p[2]);
    const T m = T((p[3] - p[2]) / (p[1] - p[0]));  // slope dr/dz, in double: p[] are exact
    // Expand around the apex of a cone: rays through or near it meet a
    // (near) double root, which the quadratic only resolves to sqrt(eps)
    // unless its coefficients are small there. Otherwise around the middle.
    const bool apex = p[2] == 0 || p[3] == 0;
    const double zc = p[3] == 0 ? p[1] : p[2] == 0 ? p[0] : 0.5 * (p[0] + p[1]);
    const Vec3<T> centre(0, 0, T(zc));
    const T tc = closest_t(o, d, centre);
    const Vec3<T> c0 = o + tc * d;
    // Bounding ball around the expansion point: the rims lie on it.
    const double hz = apex ? p[1] - p[0] : 0.5 * (p[1] - p[0]), rmax = std::max(p[2], p[3]);
    if (misses_ball(c0, centre, T(hz * hz + rmax * rmax))) return 0;
    const T e0 = r0 + m * (c0.z - z0);  // r(z) at the shifted origin
    const T e1 = m * d.z;               // its rate along the ray
    const T a = d.x * d.x + d.y * d.y - e1 * e1;
    const T hb = c0.x * d.x + c0.y * d.y - e0 * e1;
    const T c = c0.x * c0.x + c0.y * c0.y - e0 * e0;
    return quadric_between_caps(a, hb, c, c0.z, d.z, z0, z1, tc, out);
}

glm::dvec3 normal_cylinder(const double* p, const glm::dvec3& x, std::uint8_t part) {
    if (part == kPartBottom) return {0, 0, -1};
    if (part == kPartTop) return {0, 0, 1};
    // Gradient of ρ - r(z), times ρ (no division by ρ: fine at a cone apex too).
    const double m = (p[3] - p[2]) / (p[1] - p[0]);
    const double rho = std::sqrt(x.x * x.x + x.y * x.y);
    if (rho == 0) return {0, 0, m > 0 ? -1.0 : 1.0};  // apex: axis direction away from the solid
    return {x.x, x.y, -m * rho};
}

template int intersect_cylinder<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*);
template int intersect_cylinder<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*);

}  // namespace kerf::csg

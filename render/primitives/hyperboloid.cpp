// Hyperboloid of one sheet, capped: |z| < h/2 and ρ² < w² + κ·z² with
// κ = (r² - w²) / (h/2)². A line can cross the waist twice (a < 0 gives two
// infinite intervals of the quadric), hence up to two spans. κ < 0 (waist
// wider than the ends) is a capped ellipsoid barrel and works the same way.
#include "render/primitives/kinds.hpp"

namespace kerf::csg {

template <typename T>
int intersect_hyperboloid(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    const double half_h = 0.5 * p[0];
    const T zh = T(half_h), w = T(p[2]);
    const T kappa = T((p[1] * p[1] - p[2] * p[2]) / (half_h * half_h));
    const T tc = closest_t(o, d, Vec3<T>(0));
    const Vec3<T> c0 = o + tc * d;
    const double rmax = p[1] > p[2] ? p[1] : p[2];
    if (misses_ball(c0, Vec3<T>(0), T(half_h * half_h + rmax * rmax))) return 0;  // rims (or waist) inside it
    const T a = d.x * d.x + d.y * d.y - kappa * d.z * d.z;
    const T hb = c0.x * d.x + c0.y * d.y - kappa * c0.z * d.z;
    const T c = c0.x * c0.x + c0.y * c0.y - w * w - kappa * c0.z * c0.z;
    return quadric_between_caps(a, hb, c, c0.z, d.z, -zh, zh, tc, out);
}

glm::dvec3 normal_hyperboloid(const double* p, const glm::dvec3& x, std::uint8_t part) {
    if (part == kPartBottom) return {0, 0, -1};
    if (part == kPartTop) return {0, 0, 1};
    const double half_h = 0.5 * p[0];
    const double kappa = (p[1] * p[1] - p[2] * p[2]) / (half_h * half_h);
    return {x.x, x.y, -kappa * x.z};
}

template int intersect_hyperboloid<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*);
template int intersect_hyperboloid<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*);

}  // namespace kerf::csg

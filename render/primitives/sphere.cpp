// Sphere of radius r at the origin (sphere.hpp): its instantiations for
// intersect_leaf, a run of rays through one sphere, its normal.
#include "render/primitives/sphere.hpp"

namespace kerf::csg {

void intersect_sphere_rays(const Leaf& leaf, int n, const glm::dvec3* o, const glm::dvec3* d, Span<double>* out,
                           int* count) {
    for (int k = 0; k < n; ++k) count[k] = solve_sphere<double>(leaf.p, o[k], d[k], out + k * kMaxSpans);
}

glm::dvec3 normal_sphere(const double*, const glm::dvec3& x, std::uint8_t) { return x; }

// intersect_leaf's sphere (kinds.hpp): out of line, one copy of the solve.
template <typename T>
int intersect_sphere(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    return solve_sphere(p, o, d, out);
}

template int intersect_sphere<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*);
template int intersect_sphere<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*);

}  // namespace kerf::csg

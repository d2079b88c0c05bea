// Axis-aligned box lo < x < hi by slabs. (lo - o) / d (one rounding after the
// subtraction) rather than (lo - o) * (1/d): flush faces of neighbouring boxes
// then give bit-identical crossings.
#include <limits>

#include "render/primitives/kinds.hpp"

namespace kerf::csg {

template <typename T>
int intersect_box(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    constexpr T inf = std::numeric_limits<T>::infinity();
    T t0 = -inf, t1 = inf;
    std::uint8_t p0 = kPartNone, p1 = kPartNone;
    for (int i = 0; i < 3; ++i) {
        const T lo = T(p[i]), hi = T(p[i + 3]);
        if (d[i] == T(0)) {
            // Parallel to this slab: inside only strictly between its planes,
            // so a ray lying in a face plane is outside (degenerate rule).
            if (!(lo < o[i] && o[i] < hi)) return 0;
            continue;
        }
        T ta = (lo - o[i]) / d[i], tb = (hi - o[i]) / d[i];
        std::uint8_t pa = std::uint8_t(i), pb = std::uint8_t(i + 3);
        if (d[i] < T(0)) {
            const T tmp = ta; ta = tb; tb = tmp;
            pa = std::uint8_t(i + 3);
            pb = std::uint8_t(i);
        }
        // Strict comparisons: at an edge or corner the lowest axis keeps the part.
        if (ta > t0) { t0 = ta; p0 = pa; }
        if (tb < t1) { t1 = tb; p1 = pb; }
    }
    if (!(t0 < t1)) return 0;
    out[0] = Span<T>{t0, t1, p0, p1};
    return 1;
}

glm::dvec3 normal_box(const double*, const glm::dvec3&, std::uint8_t part) {
    glm::dvec3 n(0.0);
    if (part < 6) n[part % 3] = part < 3 ? -1.0 : 1.0;
    return n;
}

template int intersect_box<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*);
template int intersect_box<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*);

}  // namespace kerf::csg

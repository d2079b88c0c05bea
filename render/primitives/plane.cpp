// Half-space dot(n, x) < offset: one span, infinite at one end, or the whole
// line when the ray runs parallel inside.
#include <cmath>
#include <limits>

#include "render/primitives/kinds.hpp"

namespace kerf::csg {

template <typename T>
int intersect_plane(const double* p, const Vec3<T>& o, const Vec3<T>& d, Span<T>* out) {
    constexpr T inf = std::numeric_limits<T>::infinity();
    const Vec3<T> n{T(p[0]), T(p[1]), T(p[2])};
    const T offset = T(p[3]);
    const T dn = glm::dot(n, d);
    const T gap = offset - glm::dot(n, o);  // > 0: o strictly inside
    if (dn == T(0)) {
        if (!(gap > T(0))) return 0;  // parallel on or outside the boundary
        out[0] = Span<T>{-inf, inf, kPartNone, kPartNone};
        return 1;
    }
    const T t = gap / dn;
    if (!(std::abs(t) < inf)) {
        // |gap / dn| overflowed: the crossing is beyond any representable t.
        if (!(gap > T(0))) return 0;
        out[0] = Span<T>{-inf, inf, kPartNone, kPartNone};
        return 1;
    }
    out[0] = dn > T(0) ? Span<T>{-inf, t, kPartNone, kPartSide} : Span<T>{t, inf, kPartSide, kPartNone};
    return 1;
}

glm::dvec3 normal_plane(const double* p, const glm::dvec3&, std::uint8_t) { return {p[0], p[1], p[2]}; }

template int intersect_plane<float>(const double*, const Vec3<float>&, const Vec3<float>&, Span<float>*);
template int intersect_plane<double>(const double*, const Vec3<double>&, const Vec3<double>&, Span<double>*);

}  // namespace kerf::csg

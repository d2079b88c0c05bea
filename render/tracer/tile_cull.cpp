// CsgTracer::misses_all: does every ray of a tile miss the scene? (and
// tile_misses_box: a given box, the ground's shadow, render/ground.hpp.) The rays of
// an image tile lie in the convex hull of its four corner rays (one apex and
// four directions for a pinhole camera, four origins and one direction for
// an orthographic one), so a box outside one of the four side planes of that
// hull is missed by all of them. render() then fills the tile with what a
// miss gives, without tracing: most tiles of a simple scene are background.
#include <cmath>

#include "render/tracer/build.hpp"

namespace kerf::render {

bool CsgTracer::misses_all(const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4]) const {
    return tile_misses_box(impl_->reach, o, d);
}

bool tile_misses_box(const csg::Aabb& box, const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4]) {
    if (box.empty()) return true;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(box.lo[i]) || !std::isfinite(box.hi[i])) return false;  // unbounded units
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4, k = (i + 2) % 4;  // corners go round the tile
        // The plane through ray i that also holds ray j (pinhole: both
        // directions; orthographic: the direction and the step between origins).
        glm::dvec3 n = glm::cross(d[i], o[j] + d[j] - o[i]);
        const double len = glm::length(n);
        if (!(len > 0)) return false;
        n /= len;
        if (glm::dot(n, o[k] + d[k] - o[i]) < 0) n = -n;  // the tile's inside is positive
        // Outside by a margin far above round-off: the box's nearest corner.
        const glm::dvec3 corner(n.x > 0 ? box.hi.x : box.lo.x, n.y > 0 ? box.hi.y : box.lo.y,
                                n.z > 0 ? box.hi.z : box.lo.z);
        const double slack = 1e-9 * (glm::length(corner) + glm::length(o[i]) + 1e-300);
        if (glm::dot(n, corner - o[i]) < -slack) return true;
    }
    return false;
}

}  // namespace kerf::render

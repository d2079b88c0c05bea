// CsgTracer::misses_all: does every ray of a tile miss the scene? (and
// tile_misses_box: a given box, the ground's shadow, render/ground.hpp.) The rays of
// an image tile lie in the convex hull of its four corner rays (one apex and
// four directions for a pinhole camera, four origins and one direction for
// an orthographic one), so a box outside one of the four side planes of that
// hull is missed by all of them. render() then fills the tile with what a
// miss gives, without tracing: most tiles of a simple scene are background.
// A scene of few units is asked again unit by unit, each by its ball when it
// has one (unit_balls.hpp): a sphere's box reaches far past its outline, and
// the pixels between were traced only to be rejected by that ball. So is a
// crowd of balls seen by a pinhole camera (Impl::cull_from): near_units
// lists the units a tile's rays may meet, and its blocks ask only those.
#include <cmath>

#include "render/tracer/build.hpp"

namespace kerf::render {

namespace {

// The side planes of the hull of four corner rays: unit normals pointing
// inside, each through the origin of its first ray. Planes are found in
// order round the quad; one degenerate plane (two corner rays the same, as
// at a far origin or a vanishing field of view) leaves none: the plane
// before it takes its side from a corner that then lies in that plane, a
// sign of round-off, so no plane of such a quad can be trusted.
struct HullPlanes {
    glm::dvec3 n[4];
    int count = 0;
};

HullPlanes hull_planes(const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4]) {
    HullPlanes h;
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4, k = (i + 2) % 4;  // corners go round the tile
        // The plane through ray i that also holds ray j (pinhole: both
        // directions; orthographic: the direction and the step between origins).
        glm::dvec3 n = glm::cross(d[i], o[j] + d[j] - o[i]);
        const double len = glm::length(n);
        if (!(len > 0)) return HullPlanes{};
        n /= len;
        if (glm::dot(n, o[k] + d[k] - o[i]) < 0) n = -n;  // the tile's inside is positive
        h.n[h.count++] = n;
    }
    return h;
}

// Whether `box` lies outside one of the planes h.n[0, upto) by a margin far
// above round-off (its nearest corner). Empty boxes always, unbounded never.
bool box_outside(const csg::Aabb& box, const HullPlanes& h, int upto, const glm::dvec3 (&o)[4]) {
    if (box.empty()) return true;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(box.lo[i]) || !std::isfinite(box.hi[i])) return false;  // unbounded units
    for (int i = 0; i < upto; ++i) {
        const glm::dvec3& n = h.n[i];
        const glm::dvec3 corner(n.x > 0 ? box.hi.x : box.lo.x, n.y > 0 ? box.hi.y : box.lo.y,
                                n.z > 0 ? box.hi.z : box.lo.z);
        const double slack = 1e-9 * (glm::length(corner) + glm::length(o[i]) + 1e-300);
        if (glm::dot(n, corner - o[i]) < -slack) return true;
    }
    return false;
}

// The ball test a traced ray makes first (unit_ball_misses) widens the
// ball by 4·eps_ray (eps_per_distance·|o|) and ball_slack·|c - o|₁; over
// the hull, |o| and |c - o|₁ are at most their largest at the corners
// (both convex in o). A ball outside a side plane by that radius, and by
// 1e-9 of the distances beyond it, is outside the chord of every ray of
// the hull: each traced ray's ball test would reject the unit.
bool ball_outside(const Ball& b, const HullPlanes& h, const glm::dvec3 (&o)[4], double eps_per_distance,
                  double ball_slack) {
    double o_max = 0, w_max = 0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 w = b.c - o[i];
        o_max = std::max(o_max, glm::length(o[i]));
        w_max = std::max(w_max, std::abs(w.x) + std::abs(w.y) + std::abs(w.z));
    }
    const double r = grown_radius(b.r, 4 * eps_per_distance * o_max, ball_slack, w_max);
    for (int i = 0; i < h.count; ++i) {
        const double slack = 1e-9 * (w_max + r + glm::length(o[i]) + 1e-300);
        if (glm::dot(h.n[i], b.c - o[i]) < -(r + slack)) return true;
    }
    return false;
}

// Whether cull unit k lies outside one of the hull's planes: its ball
// (from the camera's position, found once, when all four corner rays start
// there: the same numbers ball_outside finds), else its box.
bool unit_outside(const CsgTracer::Impl& impl, std::size_t k, const HullPlanes& h, const glm::dvec3 (&o)[4],
                  bool from_origin) {
    const CsgTracer::Impl::CullBound& u = impl.cull_units[k];
    if (u.ball.r < 0) return box_outside(u.box, h, h.count, o);
    if (!from_origin) return ball_outside(u.ball, h, o, impl.eps_per_distance, impl.ball_slack);
    const CsgTracer::Impl::CullFrom& f = impl.cull_from[k];
    for (int i = 0; i < h.count; ++i)
        if (glm::dot(h.n[i], f.w) < -f.r) return true;
    return false;
}

bool from_origin(const CsgTracer::Impl& impl, const glm::dvec3 (&o)[4]) {
    if (impl.cull_from.empty()) return false;
    for (int i = 0; i < 4; ++i)
        if (o[i] != impl.cull_origin) return false;
    return true;
}

}  // namespace

bool CsgTracer::misses_all(const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4]) const {
    const HullPlanes h = hull_planes(o, d);
    if (box_outside(impl_->reach, h, h.count, o)) return true;
    if (impl_->cull_units.empty()) return false;
    const bool origin = from_origin(*impl_, o);
    for (std::size_t k = 0; k < impl_->cull_units.size(); ++k)
        if (!unit_outside(*impl_, k, h, o, origin)) return false;
    return true;
}

int CsgTracer::near_units(const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4], const std::uint32_t* among, int n,
                          std::uint32_t* near) const {
    if (impl_->cull_units.empty()) return -1;
    const HullPlanes h = hull_planes(o, d);
    if (box_outside(impl_->reach, h, h.count, o)) return 0;
    const bool origin = from_origin(*impl_, o);
    int count = 0;
    if (!among) {
        for (std::uint32_t k = 0; k < impl_->cull_units.size(); ++k)
            if (!unit_outside(*impl_, k, h, o, origin)) near[count++] = k;
        return count;
    }
    for (int i = 0; i < n; ++i)
        if (!unit_outside(*impl_, among[i], h, o, origin)) near[count++] = among[i];
    return count;
}

std::size_t CsgTracer::cull_unit_count() const { return impl_->cull_units.size(); }

bool tile_misses_box(const csg::Aabb& box, const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4]) {
    const HullPlanes h = hull_planes(o, d);
    return box_outside(box, h, h.count, o);
}

}  // namespace kerf::render

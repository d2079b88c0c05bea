#include "render/ground.hpp"

#include <cmath>

namespace kerf::render {

csg::Aabb ground_shadow_box(const csg::Scene& scene) {
    csg::Aabb out;
    const csg::Aabb solid = scene.bounds();
    if (!scene.ground.on || solid.empty()) return out;
    const double z0 = scene.ground.z;
    const csg::Aabb everywhere = csg::Aabb::everything();
    auto corner = [](const csg::Aabb& b, int k) {
        return glm::dvec3((k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z);
    };
    for (const csg::Light& l : scene.lights) {
        if (!l.shadows) continue;
        if (l.directional) {
            const glm::dvec3 d = glm::normalize(l.direction);
            if (!(d.z < 0)) continue;  // it never lights the ground's upper side
            if (!(d.z < -1e-6)) return everywhere;
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 p = corner(solid, k);
                out.extend(p + d * ((z0 - p.z) / d.z));
            }
            continue;
        }
        const double r = std::max(l.radius, 0.0);
        if (l.position.z + r <= z0) continue;  // below the ground: lights none of it
        const csg::Aabb source{l.position - glm::dvec3(r), l.position + glm::dvec3(r)};
        if (!(source.lo.z > solid.hi.z + 1e-9 * (std::abs(solid.hi.z) + 1))) return everywhere;
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 s = corner(source, i);
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 p = corner(solid, k);
                out.extend(s + (p - s) * ((s.z - z0) / (s.z - p.z)));
            }
        }
    }
    if (out.empty()) return out;
    // Round-off of the projections: a margin far above it.
    const glm::dvec3 pad(1e-9 * (glm::length(out.hi - out.lo) + glm::length(out.lo) + glm::length(out.hi)));
    out.lo -= pad, out.hi += pad;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(out.lo[i]) || !std::isfinite(out.hi[i])) return everywhere;
    return out;
}

}  // namespace kerf::render

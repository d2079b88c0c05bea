#include "lower/defaults.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kerf {

bool finite_box(const csg::Aabb& b) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(b.lo[i]) || !std::isfinite(b.hi[i])) return false;
    return !b.empty();
}

csg::Aabb framing_box(const csg::Scene& scene) {
    const csg::Aabb root = scene.bounds();
    if (finite_box(root)) return root;
    csg::Aabb frame;
    for (const csg::Leaf& leaf : scene.leaves)
        if (finite_box(leaf.bounds)) frame.extend(leaf.bounds);
    if (frame.empty()) frame = {glm::dvec3(-1), glm::dvec3(1)};
    return frame;
}

csg::Camera default_camera(const csg::Aabb& frame, const SourceLoc& loc) {
    csg::Camera cam;
    cam.fov = 40;
    cam.up = {0, 0, 1};
    const glm::dvec3 centre = 0.5 * (frame.lo + frame.hi);
    double radius = 0.5 * glm::length(frame.hi - frame.lo);
    // A point still needs a camera some distance away; any solid of
    // positive size is framed at its own size, however small or large
    // (lowering has checked that it lies in the renderable range).
    if (!(radius > 0)) radius = std::max(1.0, glm::length(centre)) * 1e-6;
    char text[160];
    if (radius < 0.5 / csg::kRenderableRange) {
        std::snprintf(text, sizeof text, "the solid is %g across: too small to frame (kerf frames solids at least %g across)",
                      2 * radius, 1 / csg::kRenderableRange);
        throw SourceError(loc, text);
    }
    if (radius < 1e-12 * glm::length(centre)) {
        std::snprintf(text, sizeof text,
                      "the solid is %g across at %g from the origin: too small there to frame (give a camera())",
                      2 * radius, glm::length(centre));
        throw SourceError(loc, text);
    }
    const double half = glm::radians(cam.fov / 2);
    const double distance = 1.05 * radius / std::sin(half);
    cam.look_at = centre;
    cam.position = centre + distance * glm::normalize(glm::dvec3(1, -1, 0.8));
    return cam;
}

std::vector<csg::Light> default_lights(const csg::Camera& cam) {
    glm::dvec3 to_camera = cam.position - cam.look_at;
    double distance = glm::length(to_camera);
    // A user camera may sit on its look_at point or look along its up vector.
    if (!(distance > 0)) to_camera = {1, -1, 0.8}, distance = glm::length(to_camera);
    const glm::dvec3 forward = -to_camera / distance;
    glm::dvec3 side = glm::cross(forward, cam.up);
    if (!(glm::length(side) > 1e-9)) side = glm::cross(forward, glm::dvec3(0, 1, 0));
    if (!(glm::length(side) > 1e-9)) side = glm::cross(forward, glm::dvec3(1, 0, 0));
    const glm::dvec3 right = glm::normalize(side);
    const glm::dvec3 up = glm::cross(right, forward);
    csg::Light key;
    key.position = cam.position + distance * (0.7 * up - 0.6 * right);
    key.intensity = 1.0;
    csg::Light head;
    head.position = cam.position;
    head.intensity = 0.25;
    return {key, head};
}

}  // namespace kerf

// The studio look's ground (csg::Ground, docs/language.md "The default
// look"): where a ray meets it, and the box on it where the solid can cast
// a shadow, which tiles must trace (tiles.hpp). Its shading is the
// Shader's (shading.cpp): the miss colour, darkened by the shadow.
#pragma once
#include <limits>

#include "csg/scene.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

// The ray's t where it meets the ground coming down from above, inside
// (tnear, tfar); +inf when it does not (the ground is seen from above only).
inline double ground_distance(const csg::Ground& g, const TraceRay& ray) {
    constexpr double none = std::numeric_limits<double>::infinity();
    if (!g.on || !(ray.d.z < 0) || !(ray.o.z > g.z)) return none;
    const double t = (g.z - ray.o.z) / ray.d.z;
    return t > ray.tnear && t < ray.tfar ? t : none;
}

// A box in the ground's plane holding every point where the solid can stand
// between it and a shadow-casting light: the corners of the solid's box
// projected onto the plane from the corners of the cube round each light's
// sphere (or along a distant light's direction); each projection is a
// central (or parallel) one, so the hull of those points holds the shadow.
// Empty when the ground is off or nothing casts a shadow on it; infinite
// when a light is not wholly above the solid's box (nothing then bounds it).
csg::Aabb ground_shadow_box(const csg::Scene& scene);

}  // namespace kerf::render

// Cosine-weighted directions over the hemisphere about a unit normal, for
// ambient occlusion (ao.cpp) and the path tracer's diffuse bounces
// (integrator_path.cpp): Malley's method, a uniform point of the unit disk
// lifted onto the hemisphere, in a frame about n built without branches
// (Duff et al.). The density is cos θ / π.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace kerf::render {

// `u` in [0, 1)²: u.x picks the radius² on the disk, u.y the angle.
inline glm::dvec3 cosine_direction(const glm::dvec3& n, const glm::dvec2& u) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1 / (sign + n.z), b = n.x * n.y * a;
    const glm::dvec3 t{1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    const glm::dvec3 s{b, sign + n.y * n.y * a, -n.y};
    const double r = std::sqrt(u.x), phi = 2 * std::numbers::pi * u.y;
    return r * std::cos(phi) * t + r * std::sin(phi) * s + std::sqrt(std::max(0.0, 1 - u.x)) * n;
}

}  // namespace kerf::render

// The optics of a smooth dielectric boundary (docs/language.md, "Glass"):
// Fresnel's equations for unpolarised light, Snell's law, total internal
// reflection and Beer–Lambert absorption. Pure functions of directions and
// cosines: shading.cpp applies them where the CSG tracer says a ray enters
// or leaves a transparent solid.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

namespace kerf::render {

// Reflectance of unpolarised light arriving at cosine `cos_i` (> 0, from the
// normal on the arriving side) at a boundary with index ratio
// eta = n_from / n_to: the mean of the s and p reflectances (exact, not
// Schlick's approximation). 1 under total internal reflection; `cos_t`
// gets the cosine of the transmitted ray (0 then).
inline double fresnel_dielectric(double cos_i, double eta, double& cos_t) {
    const double sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t >= 1) {
        cos_t = 0;
        return 1;
    }
    cos_t = std::sqrt(1 - sin2_t);
    const double rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const double rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

// Snell's law: the transmitted unit direction of unit `d` crossing a
// boundary whose unit normal `n` faces the arriving ray (dot(d, n) = −cos_i),
// with cos_t from fresnel_dielectric (no total internal reflection).
inline glm::dvec3 refract_direction(const glm::dvec3& d, const glm::dvec3& n, double eta, double cos_i, double cos_t) {
    return glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
}

inline glm::dvec3 mirror_direction(const glm::dvec3& d, const glm::dvec3& n) { return d - 2 * glm::dot(d, n) * n; }

// The share of light left after `distance` inside a medium absorbing
// `sigma` per unit length in each channel. A clear channel (σ = 0) keeps
// all of it over any distance, also an infinite one (a ray that never
// leaves an unbounded glass solid), where 0 · ∞ would be NaN.
inline glm::dvec3 beer_lambert(const glm::dvec3& sigma, double distance) {
    glm::dvec3 k;
    for (int c = 0; c < 3; ++c) k[c] = sigma[c] == 0 ? 1.0 : std::exp(-sigma[c] * distance);
    return k;
}

}  // namespace kerf::render

// The geometry of kerf's lights (docs/language.md §11): how much of a
// light's intensity reaches a point before shadows (spot cone, inverse
// square), and where the shadow rays of a spherical light go. Shading
// (shading.cpp) adds the surface's response.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/sampler.hpp"

namespace kerf::render {

// The spot's cone: 1 within spot_angle of its axis, 0 beyond spot_angle +
// spot_falloff, smoothstep between (a hard edge when the falloff is 0).
// `to_point`: unit vector from the light to the lit point; the light's
// direction is of unit length too (the shader normalises it once).
inline double spot_factor(const csg::Light& light, const glm::dvec3& to_point) {
    const double angle = std::acos(std::clamp(glm::dot(light.direction, to_point), -1.0, 1.0)) * (180 / M_PI);
    if (angle <= light.spot_angle) return 1;
    if (angle >= light.spot_angle + light.spot_falloff) return 0;
    const double t = (light.spot_angle + light.spot_falloff - angle) / light.spot_falloff;
    return t * t * (3 - 2 * t);
}

// The part of `light.intensity` that arrives at distance `dist` in
// direction `to_point` from a light with a position.
inline double arriving(const csg::Light& light, const glm::dvec3& to_point, double dist) {
    double k = light.intensity;
    if (light.inverse_square) k /= dist * dist;
    if (light.spot) k *= spot_factor(light, to_point);
    return k;
}

// Where a light is seen from `origin`: the unit direction `l` towards it,
// its distance (infinite for a distant light) and the part of its
// intensity that arrives (arriving()). False when the point sits on the
// light or nothing arrives.
struct LightView {
    glm::dvec3 l;
    double dist, k;
};
// Inlined: called once per light per shading point, and out of line its
// LightView went through memory and was read back wider than written (a
// store-forwarding stall, ~1 % of a render's cycles).
[[gnu::always_inline]] inline bool view_light(const csg::Light& light, const glm::dvec3& origin, LightView& v) {
    if (light.directional) {
        v = {-light.direction, std::numeric_limits<double>::infinity(), light.intensity};
    } else {
        v.l = light.position - origin;
        v.dist = glm::length(v.l);
        if (v.dist == 0) return false;
        v.l /= v.dist;
        v.k = arriving(light, -v.l, v.dist);
    }
    return v.k > 0;
}

// Stirs the bits of v into the generator state h.
inline void mix_bits(std::uint64_t& h, const glm::dvec3& v) {
    for (int i = 0; i < 3; ++i) {
        std::uint64_t bits;
        std::memcpy(&bits, &v[i], sizeof bits);
        h ^= bits;
        splitmix64(h);
    }
}

// A generator for the shadow rays at one shading point: seeded by the
// point's bits and the light, so a pixel's value depends only on its own
// rays, never on the thread that traced it or the order of pixels.
inline std::uint64_t shading_rng(const glm::dvec3& p, std::size_t light) {
    std::uint64_t h = 0x243F6A8885A308D3ull ^ light;
    mix_bits(h, p);
    return h;
}

// A direction towards a sphere of radius r whose centre is `dist` away in
// unit direction `l` (dist > r), uniform over the cone the sphere fills
// seen from the point, from a stratified (u, v) in [0, 1)²; `reach` gets
// the distance to the sphere's near side along it.
struct ConeBasis {
    glm::dvec3 l, t, b;
    double cos_max, dist, r;
    ConeBasis(const glm::dvec3& l_, double dist_, double r_) : l(l_), dist(dist_), r(r_) {
        const double s = r / dist;
        cos_max = std::sqrt(std::max(0.0, 1 - s * s));
        t = glm::normalize(std::abs(l.x) < 0.9 ? glm::cross(l, glm::dvec3(1, 0, 0)) : glm::cross(l, glm::dvec3(0, 1, 0)));
        b = glm::cross(l, t);
    }
    glm::dvec3 direction(const glm::dvec2& uv, double& reach) const {
        const double c = 1 - uv.x * (1 - cos_max), s = std::sqrt(std::max(0.0, 1 - c * c));
        const double phi = 2 * M_PI * uv.y;
        reach = dist * c - std::sqrt(std::max(0.0, r * r - dist * dist * s * s));
        return c * l + s * (std::cos(phi) * t + std::sin(phi) * b);
    }
};

}  // namespace kerf::render

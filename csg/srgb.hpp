// The one sRGB curve of kerf. Colour convention (docs/language.md §10): every colour a
// user writes — `color([r,g,b])`, `color("steelblue")`, `material(color=...)`,
// `light(color=...)`, `background(...)` — is an sRGB-encoded display colour
// in [0,1], as in OpenSCAD, CSS and every paint program, so `[0.5,0.5,0.5]`
// looks like the mid grey a user picked. Shading needs linear light, so the
// interpreter converts with srgb_to_linear() when it builds a csg::Material
// (whose colours are linear RGB, as everything in the contract) and the
// renderer encodes back to sRGB, with this same curve, only when it writes
// 8-bit images (render/image/srgb_bytes.hpp). Alpha is coverage, not light: never converted.
#pragma once
#include <cmath>

#include <glm/glm.hpp>

namespace kerf::csg {

// IEC 61966-2-1 piecewise sRGB transfer function (not the 2.2 power
// approximation): exact at 0 and 1, linear segment near black. Values outside
// [0,1] are extended by odd symmetry/continuation rather than clamped, so
// out-of-gamut inputs stay monotonic; callers validate ranges if they must.
inline double srgb_to_linear(double c) {
    if (std::abs(c) <= 0.04045) return c / 12.92;
    const double m = std::pow((std::abs(c) + 0.055) / 1.055, 2.4);
    return c < 0 ? -m : m;
}

inline double linear_to_srgb(double c) {
    if (std::abs(c) <= 0.0031308) return c * 12.92;
    const double m = 1.055 * std::pow(std::abs(c), 1.0 / 2.4) - 0.055;
    return c < 0 ? -m : m;
}

inline glm::dvec3 srgb_to_linear(glm::dvec3 c) {
    return {srgb_to_linear(c.x), srgb_to_linear(c.y), srgb_to_linear(c.z)};
}

inline glm::dvec3 linear_to_srgb(glm::dvec3 c) {
    return {linear_to_srgb(c.x), linear_to_srgb(c.y), linear_to_srgb(c.z)};
}

}  // namespace kerf::csg

// Which estimators of the light from spherical lights the path tracer's
// diffuse bounces use (integrator_path.hpp): both, weighted by multiple
// importance sampling (the renderer's choice), or one alone. Tests render
// all three: they converge to the same image.
#pragma once
#include <cstdint>

namespace kerf::render {

enum class PathLighting : std::uint8_t { Mis, BsdfOnly, LightOnly };

}  // namespace kerf::render

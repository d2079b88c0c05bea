// Arbitrary output values (docs/spec.md §7): one ray through each pixel
// centre, whatever the sample count: depth (+inf on a miss), the world
// normal of the final solid (0 on a miss), or the number of primitive
// intervals found along the ray.
#pragma once
#include "render/camera.hpp"
#include "render/render.hpp"
#include "render/shading.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

// The channels and meaning of an AOV's image (Aov::None: colour).
int aov_channels(Aov aov);
ImageContent aov_content(Aov aov);

// Writes pixel (x, y)'s AOV into `out`; `traced` false: a known miss.
void aov_pixel(Aov aov, const CameraModel& camera, const CsgTracer& tracer, int x, int y, ThreadState& ts,
               bool traced, float* out);

}  // namespace kerf::render

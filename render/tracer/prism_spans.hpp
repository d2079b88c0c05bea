// Prism and lathe leaves' spans along a ray (prism_spans.cpp): any number of them, so
// they bypass intersect_leaf's two-span buffers as mesh leaves do.
#pragma once
#include <cstdint>

namespace kerf::render {

struct RayState;

// Pushes the spans of prism or lathe leaf `leaf_id` overlapping [a, b]; returns the count.
std::uint32_t prism_spans(RayState& es, std::uint32_t leaf_id, double a, double b);

}  // namespace kerf::render

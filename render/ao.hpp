// Ambient occlusion (docs/spec.md §12, `ambient_occlusion(samples,
// distance)`): the share of the cosine-weighted hemisphere above a surface
// point from which nothing of the scene lies within `distance`, estimated by
// shadow rays through the CSG tracer (the soft lights' query). The samples
// are stratified over the unit square (SamplePattern) and mapped to the
// hemisphere by Malley's method (a uniform point of the unit disk lifted
// onto the hemisphere), jittered by a generator the caller seeds from the
// shading point, so the estimate is the same for any thread count.
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "render/sampler.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

// `n` the unit normal facing the viewer, `origin` already offset off the
// surface; `distance` > 0 (infinity: any blocker counts). Returns a value in
// [0, 1]: 1 unoccluded. `rays` counts the shadow rays traced.
double ambient_visibility(const CsgTracer& tracer, const glm::dvec3& origin, const glm::dvec3& n, double distance,
                          const SamplePattern& pattern, std::uint64_t rng, TraceScratch& scratch, std::uint64_t& rays);

}  // namespace kerf::render

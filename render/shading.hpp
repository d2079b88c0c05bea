// Blinn–Phong shading with hard and soft shadows (lights.hpp) and mirror reflection (docs/spec.md §5–6),
// on top of the CSG tracer. One Shader is shared by all render threads.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/sampler.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

struct RayCounts {
    std::uint64_t primary = 0, shadow = 0, reflect = 0;
};

// Everything one render thread owns: no sharing, no locks per ray.
struct ThreadState {
    TraceScratch scratch;
    RayCounts rays;
    std::uint64_t refined_pixels = 0;  // adaptive anti-aliasing
};

class Shader {
public:
    Shader(const csg::Scene& scene, const CsgTracer& tracer, int max_reflect_depth);
    // Linear RGB seen along the ray; `depth` counts reflections so far.
    // `surface`, if given, gets 0 for a miss, else an id of the surface the
    // ray hit (leaf and cut face), for adaptive anti-aliasing.
    glm::dvec3 radiance(const TraceRay& ray, int depth, ThreadState& ts, std::uint32_t* surface = nullptr) const;

private:
    const csg::Scene& scene_;
    const CsgTracer& tracer_;
    int max_depth_;
    std::vector<csg::Light> lights_;       // the scene's, directions of unit length
    std::vector<SamplePattern> patterns_;  // per light: where its shadow rays go
};

}  // namespace kerf::render

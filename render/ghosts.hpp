// The `%` and `#` ghosts over the image (csg/ghosts.hpp, docs/openscad.md
// "Modifiers"), as OpenSCAD's preview blends them: every ghost surface a
// camera ray crosses in front of the solid's first hit (or on it: a `#`
// part's own faces) is laid over what the ray sees behind it, nearest
// last, with its material's opacity; back faces count, so a ghost box shows
// its far side through its near one. Shaded by a light at the eye (form
// without shadows: ghosts neither cast nor receive any).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/shading.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

class GhostLayers {
public:
    // `scene` and `solid` (its tracer) outlive this; one tracer per ghost scene.
    GhostLayers(const csg::Scene& scene, const CsgTracer& solid, bool use_float);
    ~GhostLayers();
    // Where a ray can meet a ghost: tiles whose rays all miss it need no look.
    const csg::Aabb& bounds() const { return bounds_; }

    // What the camera ray sees: `behind` (the solid, ground or background it
    // shows) under the ghosts in front. `opacity`, if given, gets the share
    // of `behind` they hide; `surface` (if given and a ghost is crossed) is
    // mixed with the nearest ghost surface's id, so adaptive anti-aliasing
    // sees a ghost's outline as an edge.
    glm::dvec3 over(const TraceRay& ray, const glm::dvec3& behind, ThreadState& ts, double* opacity = nullptr,
                    std::uint32_t* surface = nullptr) const;

private:
    struct Layer {
        const csg::Scene* scene;
        std::unique_ptr<CsgTracer> tracer;
    };
    const CsgTracer& solid_;
    csg::Fog fog_;  // ghost surfaces are fogged by their distance, as the solid's
    std::vector<Layer> layers_;
    csg::Aabb bounds_;
};

}  // namespace kerf::render

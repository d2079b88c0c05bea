// Blinn–Phong shading with hard and soft shadows (lights.hpp), mirror and
// glossy reflection, and glass: refraction through the CSG tracer's spans
// with Fresnel, total internal reflection and absorption (optics.hpp;
// docs/language.md, "Glass"), on top of the CSG tracer. One Shader is
// shared by all render threads.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/lights.hpp"
#include "render/sampler.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

struct RayCounts {
    std::uint64_t primary = 0, shadow = 0, reflect = 0, refract = 0;
};

// Everything one render thread owns: no sharing, no locks per ray.
struct ThreadState {
    TraceScratch scratch;
    std::vector<Span> spans;  // the spans of a refracted or shadow ray (reused, not reallocated)
    RayCounts rays;
    std::uint64_t refined_pixels = 0;  // adaptive anti-aliasing: pixels given aa_samples
    std::uint64_t edge_pixels = 0;     // and pixels crossed by one straight edge, located
    // Tracing one of a refined pixel's many samples: a probing light
    // (csg::Light::probe) sends 4 stratified shadow rays, not 16; the
    // pixel's mean still has 4 × its sample count.
    bool refining = false;
    // The last radiance() asked for a surface ended on the ground, whose
    // shadow is soft (only the studio look has one): adaptive AA compares
    // it as the shadowless ground, refining silhouettes, not shadow grain.
    bool on_ground = false;
    // The solid surface the last radiance() or surface() asked for a
    // surface id hit (t < 0: none): adaptive AA predicts where an edge
    // between two surfaces crosses a pixel's side from their planes.
    TraceHit hit{-1, {}};
};

class Shader {
public:
    // max_depth: how many reflections and refractions into a solid one
    // primary ray may branch into (leaving a solid continues the path at the
    // same depth). Where the depth is spent a surface is shaded as if it
    // were opaque, and an internal reflection is dropped.
    // ground: show the scene's ground (csg::Ground) if it has one; --alpha
    // renders without it (its pixels would be neither solid nor background).
    Shader(const csg::Scene& scene, const CsgTracer& tracer, int max_depth, bool ground = true);
    // What a ray known to meet no solid sees: the ground where it crosses
    // it (in the solid's shadow or not), else the background (or fog).
    glm::dvec3 missed(const TraceRay& ray, ThreadState& ts) const;
    // Linear RGB seen along the ray (outside every solid); `depth` counts
    // reflections and refractions so far.
    // `surface`, if given, gets 0 for a miss, else an id of the surface the
    // ray hit (leaf and cut face), for adaptive anti-aliasing.
    // Fog (csg::Fog) dims every ray's colour by the distance it travels.
    glm::dvec3 radiance(const TraceRay& ray, int depth, ThreadState& ts, std::uint32_t* surface = nullptr) const {
        TraceHit hit;
        const bool solid = tracer_.intersect(ray, hit, ts.scratch);
        return radiance(ray, solid, hit, depth, ts, surface);
    }
    // The same for a ray whose first hit is already known (`solid`: it has
    // one, `hit`), as CsgTracer::intersect gives it: a run of camera rays
    // is traced first and shaded after, so one ray's trace starts while the
    // last one's chain of divisions and square roots still runs, instead
    // of after that ray's shading.
    glm::dvec3 radiance(const TraceRay& ray, bool solid, const TraceHit& hit, int depth, ThreadState& ts,
                        std::uint32_t* surface = nullptr) const;
    // Only the `surface` radiance() would give, without shading.
    std::uint32_t surface(const TraceRay& ray, ThreadState& ts) const;
    // What a ray that hits nothing sees: the background, or the fog's colour.
    const glm::dvec3& miss() const { return miss_; }
    const csg::Scene& scene() const { return scene_; }
    const CsgTracer& tracer() const { return tracer_; }
    // The solid's world unit normal at `hit` (ThreadState::hit), point p.
    glm::dvec3 normal(const TraceHit& hit, const glm::dvec3& p) const { return tracer_.normal(hit, p); }

    // Linear RGB arriving at `p` along a ray that travels in unit direction
    // `d` inside the solid of material `m` from p on: absorbed on its way to
    // the solid's boundary, there split by Fresnel between the refracted ray
    // out and the reflected ray back inside.
    glm::dvec3 inside(const glm::dvec3& p, const glm::dvec3& d, const csg::Material& m, double tol, int depth,
                      ThreadState& ts) const;
    // The share of a light's colour reaching the end of a shadow ray: 0
    // behind an opaque solid, transparency·exp(−absorption·length) per
    // transparent span crossed (straight: no refraction, no caustics).
    // `from`: the surface the ray leaves (Departure), or null.
    // Inline: an opaque scene's shadow ray is one occlusion query, without
    // a call and a frame of its own round it.
    glm::dvec3 transmitted(const TraceRay& ray, ThreadState& ts, const Departure* from = nullptr) const {
        ++ts.rays.shadow;
        if (!any_transparent_) return glm::dvec3(tracer_.occluded(ray, ts.scratch, from) ? 0.0 : 1.0);
        return through_glass(ray, ts);
    }

private:
    // transmitted() in a scene with transparent solids.
    glm::dvec3 through_glass(const TraceRay& ray, ThreadState& ts) const;
    // `c` seen through the fog over `dist` (radiance()).
    [[gnu::noinline]] glm::dvec3 fogged(const glm::dvec3& c, double dist) const;
    // The colour of the surface `hit` seen along `ray`, before fog: by
    // shade_point_lit where it applies, else shade_any (out of line: its
    // frame is not set up for the common case).
    glm::dvec3 shade(const TraceRay& ray, const TraceHit& hit, int depth, ThreadState& ts) const;
    [[gnu::noinline]] glm::dvec3 shade_any(const TraceRay& ray, const TraceHit& hit, int depth, ThreadState& ts) const;
    // shade() where it comes to one point light on an opaque surface of
    // material m that mirrors nothing (or whose depth is spent), without
    // ambient occlusion (one_point_light_): the same numbers.
    glm::dvec3 shade_point_lit(const TraceRay& ray, const TraceHit& hit, const csg::Material& m, ThreadState& ts) const;
    const csg::Material& material_of(std::uint32_t leaf) const;
    // Whether the ground is in front of the solid (or of nothing) along the
    // ray, at t.
    bool ground_first(const TraceRay& ray, bool solid, const TraceHit& hit, double& t) const;
    // The ground at `p`: the miss colour darkened by the share of the
    // shadow-casting lights' light the solid blocks (csg::Ground).
    glm::dvec3 ground(const glm::dvec3& p, ThreadState& ts) const;
    // Calls ray(light, l, ndl, k, through) for each ray from `origin` (on a
    // surface of normal n) to a light that faces the surface (ndl > 0): one
    // per point light, `samples` per spherical one; k the colour arriving
    // (intensity, spot, fall-off, the sample's share), through what the
    // solid lets pass (shadows; 1 for a shadowless light); `from` as in
    // transmitted.
    template <class Ray>
    void light_rays(const glm::dvec3& origin, const glm::dvec3& n, const Departure* from, ThreadState& ts,
                    Ray&& ray) const;
    // light_rays for light `li`, a sphere seen as `view` from origin.
    template <class Ray>
    [[gnu::noinline]] void sphere_rays(std::size_t li, const LightView& view, const glm::dvec3& origin, const glm::dvec3& n,
                                       const Departure* from, ThreadState& ts, Ray& ray) const;
    // light_rays for a probing light (csg::Light::probe): 5 probe rays (its
    // rim and centre), its `samples` rays only where those disagree.
    template <class Ray>
    void probed_rays(const csg::Light& light, const ConeBasis& cone, const SamplePattern& pattern, std::uint64_t& rng,
                     const glm::dvec3& origin, const glm::dvec3& n, const glm::dvec3& share, const Departure* from,
                     ThreadState& ts, Ray&& ray) const;
    glm::dvec3 mirror(const glm::dvec3& origin, const glm::dvec3& r, const glm::dvec3& n, double roughness, int depth,
                      ThreadState& ts) const;

    const csg::Scene& scene_;
    const CsgTracer& tracer_;
    int max_depth_;
    glm::dvec3 miss_;
    bool ground_;          // the scene's ground is shown
    double ground_lift_;   // how far above the ground its shadow rays start
    csg::Aabb ground_shadow_;  // outside it nothing can shadow the ground (ground.hpp)
    bool any_transparent_ = false;  // else shadow rays only ask whether anything is in the way
    bool one_point_light_ = false;  // one light, a point (no sphere, not distant), and no ambient occlusion
    std::vector<csg::Light> lights_;       // the scene's, directions of unit length
    std::vector<SamplePattern> patterns_;  // per light: where its shadow rays go
    SamplePattern refining_{4};            // a probing light's, in a refined pixel's samples
};

}  // namespace kerf::render

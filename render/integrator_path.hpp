// `--integrator path` (docs/spec.md §12, docs/language.md "Path tracing"):
// an unbiased path tracer on the same CSG tracer and materials as the
// Whitted shader (shading.hpp). Diffuse interreflection (cosine-weighted),
// next-event estimation for every light, combined with BSDF sampling by
// multiple importance sampling (power heuristic) where a light has an area
// (spherical lights), mirror, glossy and glass bounces (optics.hpp),
// emitting surfaces and the background as light found by the paths
// themselves, Russian roulette after kRouletteFrom bounces and at most
// `max_depth` bounces. Its random stream is seeded by the camera ray's bits
// and the render seed, so a pixel depends on nothing but its own rays (any
// thread count, any crop). No heap allocation or virtual call per path.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/path_lighting.hpp"
#include "render/shading.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

class PathTracer {
public:
    static constexpr int kRouletteFrom = 3;  // bounces before Russian roulette may end a path

    PathTracer(const csg::Scene& scene, const CsgTracer& tracer, int max_depth, std::uint64_t seed,
               PathLighting lighting = PathLighting::Mis);
    // One path's estimate of the linear RGB arriving along the camera ray
    // (o, d); `surface` as Shader::radiance (0: the ray missed).
    glm::dvec3 radiance(const glm::dvec3& o, const glm::dvec3& d, ThreadState& ts, std::uint32_t* surface) const;

private:
    // Light arriving at `origin` (offset off a diffuse surface of normal n,
    // reflectance rho) from every light by next-event estimation.
    glm::dvec3 next_event(const glm::dvec3& origin, const glm::dvec3& n, const glm::dvec3& rho, std::uint64_t& rng,
                          ThreadState& ts) const;
    // The nearest spherical light the ray (origin, unit d) meets before
    // `tmax` (which becomes its distance): its index into lights_, or -1.
    int light_hit(const glm::dvec3& origin, const glm::dvec3& d, double& tmax) const;

    const csg::Scene& scene_;
    const CsgTracer& tracer_;
    int max_depth_;
    std::uint64_t seed_;
    PathLighting lighting_;
    glm::dvec3 miss_;
    std::vector<csg::Light> lights_;  // the scene's, directions of unit length
    bool any_sphere_ = false;         // a light with radius > 0: BSDF rays may hit it
};

}  // namespace kerf::render

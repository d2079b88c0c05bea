// `kerf measure`: volume, surface area, centre of mass and bounds of the
// exact solid, integrated over three grids of parallel rays, one along each
// axis (docs/spec.md §15). Along each ray the tracer's spans are exact, so
// only the 2D quadrature over the grid errs; the error estimate compares the
// grid with one of half its resolution and the three axes with each other.
#pragma once
#include <functional>
#include <cstdint>

#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::render {

struct MeasureOptions {
    int resolution = 512;           // rays per side of each grid: even, 8..16384
    int threads = 0;                // 0: all hardware threads
    bool double_precision = true;   // false: primitives intersected in float
};

struct Measurement {
    bool empty = true;              // no ray met the solid
    double volume = 0, volume_error = 0;
    double area = 0, area_error = 0;
    glm::dvec3 centroid{0.0};
    csg::Aabb bounds;               // the extreme crossings the grids found
    std::uint64_t rays = 0;
};

// Throws std::invalid_argument for a bad resolution and std::runtime_error
// for a solid without finite bounds (a plane, a half-space) or a tree deeper
// than render() takes. `progress` receives the finished fraction, one call
// at a time.
Measurement measure(const csg::Scene& scene, const MeasureOptions& options,
                    const std::function<void(double fraction)>& progress = {});

}  // namespace kerf::render

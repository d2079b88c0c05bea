// Shadow rays of a bare-sphere crowd toward a point light (README.md, "Bare
// spheres"): per unit and light, the few other units that could block a
// ray leaving that unit's sphere for the light, found once on first use.
//
// A shadow ray the shader sends from a sphere it hit starts just off that
// sphere (within `radius` of its centre, checked per ray) and ends at the
// light (within `rho`, checked): it lies in the capsule round the segment
// from the sphere's centre to the light, of radius max(radius, rho). A unit
// that could block it (its sphere's computed span overlapping the segment)
// has a point of its ball near that segment, so its ball meets the capsule
// grown by a slack far beyond the sphere test's round-off. The units whose
// balls meet it are listed (at most kMaxList; more: not listed, the ray
// walks the grid or its cone as before); the ray asks only those, with the
// same bare_sphere_blocks, and the departed unit itself is skipped as the
// ray's Departure says. Most lit points of a lattice face the light with
// nothing in that capsule (no unit asked at all); a sphere's neighbour
// that shadows part of it is the one unit asked.
//
// Slots are filled by whichever thread first asks, with the same numbers
// whichever it is (atomic words: a race writes the same values twice).
#pragma once
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "render/tracer/sphere_grid.hpp"
#include "render/tracer/unit_balls.hpp"

namespace kerf::render {

struct TowardLight {
    static constexpr int kMaxLights = 4;      // point lights with shadows served
    static constexpr std::uint32_t kMaxList = 3;
    static constexpr std::size_t kSlot = kMaxList + 1;  // words per unit and light
    // A capsule whose axis runs more than 12 quarter cells inside the
    // grid (deep in the crowd) is not listed but marked full at once: few
    // of its rays are lit, and its listing cost more than it saved (512²:
    // spheres_100000's shading and shadow rays 151 M instructions with no
    // limit, 135 / 126 / 122 / 121 M with 32 / 16 / 12 / 10 quarter cells).
    static constexpr double kMaxSteps = 12;
    static constexpr std::size_t kMaxUnits = std::size_t(1) << 18;  // kSlot words per unit and light, touched where used
    struct Light {
        glm::dvec3 p;
        double rho;  // a ray ending within rho (L1) of p counts as ending there
    };
    std::vector<Light> lights;
    std::vector<double> radius;  // per unit: a shadow ray from its sphere starts within it of the centre
    double r_small = 0;          // the smallest ball's radius
    // The cells (the crowd's own grid past the cones' units, else one of
    // its own), for listing.
    SphereGrid own_grid;
    const SphereGrid* grid = nullptr;
    // Per light, per unit: kSlot words, [0] 0 not yet listed, 1 + count
    // when listed (count <= kMaxList), kFull when more; then the units.
    static constexpr std::uint32_t kFull = 0xFFFFFFFFu;
    struct Free {
        void operator()(std::uint32_t* p) const { std::free(p); }
    };
    std::unique_ptr<std::uint32_t[], Free> slots;
    std::size_t units = 0;

    bool empty() const { return lights.empty(); }
    // Built in two steps after the balls and `reach` (build.cpp): the lights
    // and radii, which need no grid (a big crowd's are found while its grid
    // is built), then, with the crowd's grid, the grid and slots.
    void build_radii(const std::vector<Ball>& balls, const std::vector<double>& leaf_eps_of_unit, double eps_per_distance,
                     double frame_radius, const csg::Aabb& reach, const std::vector<glm::dvec3>& point_lights);
    void attach(const std::vector<Ball>& balls, const csg::Aabb& reach, const SphereGrid& crowd_grid);
    // The light a ray from unit `unit`'s sphere ends at (o + tfar·d), or
    // -1: none, or the ray starts too far from the sphere.
    int light_of(const glm::dvec3& o, const glm::dvec3& d, double tfar, std::uint32_t unit,
                 const std::vector<Ball>& balls) const {
        const glm::dvec3 w = o - balls[unit].c;
        if (!(glm::dot(w, w) <= radius[unit] * radius[unit])) return -1;
        const glm::dvec3 e = o + tfar * d;
        for (std::size_t k = 0; k < lights.size(); ++k) {
            const glm::dvec3 v = e - lights[k].p;
            if (std::abs(v.x) + std::abs(v.y) + std::abs(v.z) <= lights[k].rho) return int(k);
        }
        return -1;
    }
    // The units that may block a ray from `unit` to light k: their count
    // (written to `out`), or -1: more than kMaxList.
    int list(int k, std::uint32_t unit, const std::vector<Ball>& balls, std::uint32_t* out) const {
        std::uint32_t* slot = slots.get() + (std::size_t(k) * units + unit) * kSlot;
        std::uint32_t head = std::atomic_ref<std::uint32_t>(slot[0]).load(std::memory_order_acquire);
        if (head == 0) head = fill(k, unit, balls, slot);
        if (head == kFull) return -1;
        for (std::uint32_t i = 0; i + 1 < head; ++i)
            out[i] = std::atomic_ref<std::uint32_t>(slot[1 + i]).load(std::memory_order_relaxed);
        return int(head - 1);
    }

private:
    std::uint32_t fill(int k, std::uint32_t unit, const std::vector<Ball>& balls, std::uint32_t* slot) const;
};

}  // namespace kerf::render

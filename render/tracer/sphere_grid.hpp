// A uniform grid over the balls of a big crowd of bare spheres (more units
// than ray cones serve, Impl::kMaxTwoLevelUnits; the spheres_10000 …
// spheres_1000000 lattices): each cell lists the units whose ball, grown
// by `margin`, meets it. A ray walks the cells it crosses in order (3D
// DDA), tests each listed unit as the cones' loop does (bare_spheres.hpp),
// and stops at the first cell that lies wholly beyond its best entry: no
// box BVH, no callbacks, and no scan of every unit per cone (a third cone
// level would list wide cones from 10⁴–10⁶ units). The cells are about one
// unit's share of the crowd's box, the counts per axis rounded so that a
// lattice's spheres fall one to a cell.
//
// The answers are the box BVH's: a camera ray's entry is the smallest over
// the units, ties by unit index, whatever order they are visited in, and a
// shadow ray asks whether any unit blocks. A unit is visited in every cell
// that holds a point of its ball within `margin`; the computed entry (even a
// grazing one, off by ~1e-8 of the distance) and the walk's cell
// boundaries stray less than that for the rays `fits` admits; the others
// take the general query.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/tracer/unit_balls.hpp"

namespace kerf::render {

struct SphereGrid {
    glm::dvec3 lo{0.0}, h{1.0}, inv_h{1.0};  // the box's low corner, cell size
    int n[3] = {0, 0, 0};
    double margin = 0;                        // units listed where their ball comes within it (distance)
    double size = 0, mag = 0;                 // the box's size, |lo|₁ + |hi|₁ (round-off grows with them)
    std::vector<std::uint32_t> start;         // per cell, its first entry in `items` (and one past the last)
    std::vector<std::uint32_t> items;         // unit indices in the top BVH, ascending per cell

    bool empty() const { return start.empty(); }
    // The grid over `box` (every ball inside it) holding `balls` (per unit).
    void build(const csg::Aabb& box, const std::vector<Ball>& balls);
    // Whether a ray from `o` of direction `d` over t up to `t_hi` rounds
    // within a third of the margin: a grazing entry's t strays by ~3e-8 of
    // the distance (the square root of a discriminant's round-off), the
    // rest by ~1e-16 of the coordinates' magnitude. Else the caller takes
    // the general query.
    bool fits(const glm::dvec3& o, const glm::dvec3& d, double t_hi) const {
        const glm::dvec3 w = o - lo, e = glm::abs(d) * t_hi;
        const double o1 = std::abs(o.x) + std::abs(o.y) + std::abs(o.z);
        return 1e-7 * (size + std::abs(w.x) + std::abs(w.y) + std::abs(w.z) + e.x + e.y + e.z) + 1e-13 * (mag + o1) < margin;
    }
};

}  // namespace kerf::render

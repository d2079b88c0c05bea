// A uniform grid over the boxes of a big difference's subtrahends
// (README.md, "Tracer design"): which boxes can a short piece of a ray meet?
// The point queries of a holed plate (difference_first_entry.cpp) and its
// shadow rays ask that of a window a few degenerate rules long; a cell
// lookup answers it without an Embree query. Cells are flat arrays (CSR),
// read only after the build; a query allocates nothing.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::render {

struct BoxGrid {
    glm::dvec3 lo{0.0}, cell{1.0}, inv_cell{1.0};
    int res[3] = {0, 0, 0};
    double slack = 0;  // σ: boxes are listed in every cell within σ of them
    std::vector<std::uint32_t> first;  // per cell, then the end: offsets into `boxes`
    std::vector<std::uint32_t> boxes;  // indices into the boxes the grid was built over

    // Queries spanning more cells than this go to the BVH instead.
    static constexpr int kMaxCells = 64;

    bool empty() const { return first.empty(); }
    // Builds over `boxes` (finite, non-empty); leaves the grid empty when
    // it would not pay (few cells, or many boxes per cell).
    void build(const std::vector<csg::Aabb>& boxes);
    // Writes to `out` the index of every box that the ray o + t·d (invd:
    // 1/d per axis) meets for some t in [t0, t1] by the same slab test the
    // tracer's box test makes, and maybe a few more, each once; returns
    // their count, or -1 when the window is not finite or spans more than
    // kMaxCells cells, or more than `cap` boxes were found (ask the BVH).
    int candidates(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& invd, double t0, double t1,
                   std::uint32_t* out, int cap) const;
    // The same for every box within r (per axis) of the point x: a
    // superset of the boxes within distance r of it. `list` is set to
    // where they are: a cell's own list when one cell holds them (most
    // queries, nothing copied), else `out`.
    int near(const glm::dvec3& x, double r, std::uint32_t* out, int cap, const std::uint32_t*& list) const;
    // The cell index of x along axis i, clamped to the grid: monotone in x,
    // so overlapping intervals map to overlapping index ranges. (Truncation
    // is the floor here, x - lo being >= 0.)
    int cell_of(int i, double x) const {
        // max(0, NaN) is 0; no branches: most queries make six of these.
        return int(std::min(std::max(0.0, (x - lo[i]) * inv_cell[i]), last[i]));
    }
    double last[3] = {0, 0, 0};  // res - 1
};

}  // namespace kerf::render

// A uniform grid over the boxes of a big difference's subtrahends
// (README.md, "Tracer design"): which boxes can a short piece of a ray meet?
// The point queries of a holed plate (difference_first_entry.cpp) and its
// shadow rays ask that of a window a few degenerate rules long; a cell
// lookup answers it without an Embree query. Cells are flat arrays (CSR),
// read only after the build; a query allocates nothing.
#pragma once
#include <algorithm>
#include <cmath>
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
    // Inline: the one-cell answer (most queries) is a few loads; a call
    // and its frame were a large share of it (holes_40).
    int near(const glm::dvec3& x, double r, std::uint32_t* out, int cap, const std::uint32_t*& list) const {
        const double grow = r + 0.5 * slack + 1e-12 * (std::abs(x.x) + std::abs(x.y) + std::abs(x.z));
        const int k0[3] = {cell_of(0, x[0] - grow), cell_of(1, x[1] - grow), cell_of(2, x[2] - grow)};
        const int k1[3] = {cell_of(0, x[0] + grow), cell_of(1, x[1] + grow), cell_of(2, x[2] + grow)};
        if (((k1[0] - k0[0]) | (k1[1] - k0[1]) | (k1[2] - k0[2])) == 0) {
            const std::size_t c =
                std::size_t(k0[0]) + std::size_t(res[0]) * (std::size_t(k0[1]) + std::size_t(res[1]) * std::size_t(k0[2]));
            list = boxes.data() + first[c];
            return int(first[c + 1] - first[c]);
        }
        return near_cells(k0, k1, out, cap, list);
    }
    // near() over the cells k0..k1 (more than one).
    int near_cells(const int* k0, const int* k1, std::uint32_t* out, int cap, const std::uint32_t*& list) const;
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

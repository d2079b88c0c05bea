// The 2D acceleration of a prism section with many edges: a uniform grid
// over the section's box, each cell listing the edges that pass through
// it (conservatively: a little more than the segment). A ray's projection
// on the plane then visits only the cells near its line, and the prism
// tests the edges listed there instead of every edge
// (docs/lowering.md, "A section of thousands of edges"). Built once per
// section by the tracer and shared by every leaf that extrudes it.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::csg {

struct PrismGrid {
    glm::dvec2 lo{0}, hi{0};        // the section's box
    glm::dvec2 cell{1}, inv_cell{1};
    int nx = 0, ny = 0;             // 0: no grid (every edge is tested)
    double reach = 0;               // the largest |coordinate| of a vertex (round-off of the edge test)
    // The cells' edge lists twice, row by row (cell (i, j) is row j's i-th)
    // and column by column, so that the cells of one row, or of one
    // column, are one range: lines[a] walks along axis a (0: a column at a
    // time, x fixed; 1: a row at a time).
    struct Lines {
        std::vector<std::uint32_t> start;  // per cell, then the end: into `edges`
        std::vector<std::uint32_t> edges;  // edge indices, increasing within a cell
    } lines[2];
    bool empty() const { return nx == 0; }
};

// Sections with fewer edges get no grid: testing them all is cheaper than
// walking cells (measured in docs/lowering.md).
constexpr std::size_t kPrismGridMinEdges = 32;

// The grid of `poly` (about `cells_per_edge` cells an edge), or an empty
// one below `min_edges` edges.
PrismGrid build_prism_grid(const Polygon2& poly, std::size_t min_edges = kPrismGridMinEdges,
                           double cells_per_edge = 2);

// Calls visit(first, last) with the edge indices of the cells within
// `margin` (in each axis) of the line c + s·d, s in R, d ≠ 0: one range per
// row of cells when the line is nearer the x axis than the y axis, else
// per column (fewer, longer ranges), so an edge may come more than once.
// In double whatever precision the caller tests in: its round-off is
// covered by `margin`, which the caller sizes for its own.
template <class Visit>
void walk_prism_grid(const PrismGrid& g, glm::dvec2 c, glm::dvec2 d, double m, const Visit& visit) {
    // In cell units: the grid is [0, nx] x [0, ny].
    const glm::dvec2 C = (c - g.lo) * g.inv_cell, D = d * g.inv_cell, M = m * g.inv_cell;
    const glm::dvec2 n(g.nx, g.ny);
    constexpr double inf = std::numeric_limits<double>::infinity();
    double s0 = -inf, s1 = inf;
    for (int a = 0; a < 2; ++a) {
        if (D[a] == 0) {
            if (!(-M[a] <= C[a] && C[a] <= n[a] + M[a])) return;
            continue;
        }
        double ta = (-M[a] - C[a]) / D[a], tb = (n[a] + M[a] - C[a]) / D[a];
        if (ta > tb) std::swap(ta, tb);
        s0 = std::max(s0, ta);
        s1 = std::min(s1, tb);
    }
    if (!(s0 <= s1)) return;
    // Walk lines of cells across the axis the line moves along least.
    const int a = std::abs(D.y) <= std::abs(D.x) ? 1 : 0, b = 1 - a;
    const PrismGrid::Lines& L = g.lines[a];
    const int na = a == 1 ? g.ny : g.nx, nb = a == 1 ? g.nx : g.ny;
    // Cell coordinates are clamped before they become indices (no overflow, and floor = truncation).
    auto index = [](double v, int count) { return int(std::clamp(v, 0.0, double(count - 1))); };
    const std::uint32_t* edges = L.edges.data();
    if (D[a] == 0) {  // along the lines: the one or two the line lies in
        const double b0 = C[b] + s0 * D[b], b1 = C[b] + s1 * D[b];
        const int j0 = index(std::min(b0, b1) - M[b], nb), j1 = index(std::max(b0, b1) + M[b], nb);
        for (int i = index(C[a] - M[a], na), i1 = index(C[a] + M[a], na); i <= i1; ++i)
            visit(edges + L.start[std::size_t(i) * nb + j0], edges + L.start[std::size_t(i) * nb + j1 + 1]);
        return;
    }
    // Along s (never through the slope, which would magnify the round-off
    // of a line nearly along the rows).
    const double ya = C[a] + s0 * D[a], yb = C[a] + s1 * D[a], inv = 1 / D[a];
    for (int i = index(std::min(ya, yb) - M[a], na), i1 = index(std::max(ya, yb) + M[a], na); i <= i1; ++i) {
        // The line within line i of cells grown by the margin, as a range across it.
        double sa = (i - M[a] - C[a]) * inv, sb = (i + 1 + M[a] - C[a]) * inv;
        if (sa > sb) std::swap(sa, sb);
        sa = std::max(sa, s0);
        sb = std::min(sb, s1);
        const double x0 = C[b] + sa * D[b], x1 = C[b] + sb * D[b];
        const int j0 = index(std::min(x0, x1) - M[b], nb), j1 = index(std::max(x0, x1) + M[b], nb);
        visit(edges + L.start[std::size_t(i) * nb + j0], edges + L.start[std::size_t(i) * nb + j1 + 1]);
    }
}

}  // namespace kerf::csg

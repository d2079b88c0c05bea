// Building the section grid: the cells are about square, `cells_per_edge`
// per edge; each edge is entered, row by row, in the cells its segment
// spans within that row, grown by a millionth of a cell so that a point
// of the segment rounding to a neighbouring cell is still found there.
#include "render/primitives/prism_grid.hpp"

namespace kerf::csg {

PrismGrid build_prism_grid(const Polygon2& poly, std::size_t min_edges, double cells_per_edge) {
    PrismGrid g;
    const std::size_t n = poly.edges.size();
    if (n == 0 || n < min_edges) return g;
    g.lo = poly.lo;
    g.hi = poly.hi;
    for (const glm::dvec4& e : poly.edges) {
        g.lo = glm::min(g.lo, glm::min(glm::dvec2(e.x, e.y), glm::dvec2(e.z, e.w)));
        g.hi = glm::max(g.hi, glm::max(glm::dvec2(e.x, e.y), glm::dvec2(e.z, e.w)));
        g.reach = std::max({g.reach, std::abs(e.x), std::abs(e.y), std::abs(e.z), std::abs(e.w)});
    }
    const glm::dvec2 size = g.hi - g.lo;
    const double cells = std::clamp(cells_per_edge * double(n), 1.0, 4.0e6);
    if (size.x > 0 && size.y > 0) {
        // Square cells: nx / ny = size.x / size.y, nx · ny ≈ cells.
        const double side = std::sqrt(size.x * size.y / cells);
        g.nx = int(std::clamp(std::ceil(size.x / side), 1.0, cells));
        g.ny = int(std::clamp(std::ceil(size.y / side), 1.0, cells));
    } else {  // a zero-area section along an axis: one row or column
        g.nx = size.x > 0 ? int(std::ceil(cells)) : 1;
        g.ny = size.y > 0 ? int(std::ceil(cells)) : 1;
    }
    g.cell = glm::dvec2(size.x > 0 ? size.x / g.nx : 1, size.y > 0 ? size.y / g.ny : 1);
    g.inv_cell = 1.0 / g.cell;
    const glm::dvec2 pad = 1e-6 * g.cell;
    auto index = [](double v, int count) { return int(std::clamp(v, 0.0, double(count - 1))); };
    // Each edge's cells, found twice: to count them, then to fill them.
    auto each_cell = [&](const glm::dvec4& e, auto&& use) {
        const int r0 = index((std::min(e.y, e.w) - pad.y - g.lo.y) * g.inv_cell.y, g.ny);
        const int r1 = index((std::max(e.y, e.w) + pad.y - g.lo.y) * g.inv_cell.y, g.ny);
        for (int r = r0; r <= r1; ++r) {
            double xa = std::min(e.x, e.z), xb = std::max(e.x, e.z);
            if (r0 < r1 && e.w != e.y) {
                // The segment's x where it crosses the row's bounds (grown by pad).
                const double y0 = g.lo.y + r * g.cell.y - pad.y, y1 = g.lo.y + (r + 1) * g.cell.y + pad.y;
                double ta = (y0 - e.y) / (e.w - e.y), tb = (y1 - e.y) / (e.w - e.y);
                if (ta > tb) std::swap(ta, tb);
                ta = std::clamp(ta, 0.0, 1.0);
                tb = std::clamp(tb, 0.0, 1.0);
                const double x0 = e.x + ta * (e.z - e.x), x1 = e.x + tb * (e.z - e.x);
                xa = std::min(x0, x1);
                xb = std::max(x0, x1);
            }
            const int c0 = index((xa - pad.x - g.lo.x) * g.inv_cell.x, g.nx);
            const int c1 = index((xb + pad.x - g.lo.x) * g.inv_cell.x, g.nx);
            for (int c = c0; c <= c1; ++c) use(r, c);
        }
    };
    // Row-major (lines[1]) and column-major (lines[0]) lists.
    for (int a = 0; a < 2; ++a) {
        PrismGrid::Lines& L = g.lines[a];
        auto at = [&](int r, int c) {
            return a == 1 ? std::size_t(r) * std::size_t(g.nx) + std::size_t(c)
                          : std::size_t(c) * std::size_t(g.ny) + std::size_t(r);
        };
        L.start.assign(std::size_t(g.nx) * std::size_t(g.ny) + 1, 0);
        for (const glm::dvec4& e : poly.edges) each_cell(e, [&](int r, int c) { ++L.start[at(r, c) + 1]; });
        for (std::size_t k = 1; k < L.start.size(); ++k) L.start[k] += L.start[k - 1];
        L.edges.resize(L.start.back());
        std::vector<std::uint32_t> fill(L.start.begin(), L.start.end() - 1);
        for (std::uint32_t i = 0; i < n; ++i) each_cell(poly.edges[i], [&](int r, int c) { L.edges[fill[at(r, c)]++] = i; });
    }
    return g;
}

}  // namespace kerf::csg

// The subtrahend grid (box_grid.hpp). Why a query never misses a box the
// tracer's slab test keeps: a box is listed in every cell whose extent
// [lo + k·cell, lo + (k+1)·cell] comes within σ/2 of it (σ is far above
// the round-off of the cell index, a floor of a product); a ray point the
// slab test accepts lies within δ (the test's round-off, a bound from |o|
// and |t·d| per ray) of a point q of the box, so q's cell is listed and the
// ray passes within δ of it. So the query takes every cell within σ/2 + δ
// of the window's end points' bounding box, and when that is more than one
// cell, keeps those whose box grown by σ/2 + δ the ray crosses in the
// window (a slab test whose own round-off is again far below σ/2).
#include "render/tracer/box_grid.hpp"

#include <algorithm>
#include <cmath>

namespace kerf::render {

namespace {

// Cells per box along an axis, about: cells ~1/3 of the median box wide,
// so a point query's cell holds few boxes (holes_40 at 512²: 0.4 % fewer
// instructions than 1.5 per box), within a budget of cells per box.
constexpr double kCellsPerBox = 3;
constexpr std::size_t kCellsPerItem = 8;  // at most this many cells per box in all
constexpr double kMaxPerCell = 8;         // more boxes per cell on average: the BVH is better
constexpr double kMaxGridCells = 1 << 22;  // 16 MB of cell offsets at most (10⁶ subtrahends)

double max_abs(const glm::dvec3& v) { return std::max(std::max(std::abs(v.x), std::abs(v.y)), std::abs(v.z)); }
double sum_abs(const glm::dvec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

// The boxes of cell k (each once).
int one_cell(const BoxGrid& g, const int* k, std::uint32_t* out, int cap) {
    const std::size_t c = std::size_t(k[0]) + std::size_t(g.res[0]) * (std::size_t(k[1]) + std::size_t(g.res[1]) * std::size_t(k[2]));
    const int n = int(g.first[c + 1] - g.first[c]);
    if (n > cap) return -1;
    std::copy(g.boxes.data() + g.first[c], g.boxes.data() + g.first[c + 1], out);
    return n;
}

// Appends the boxes of cell c not yet in out[0, n); false past `cap`.
bool add_cell(const BoxGrid& g, std::size_t c, std::uint32_t* out, int& n, int cap) {
    for (std::uint32_t e = g.first[c]; e < g.first[c + 1]; ++e) {
        const std::uint32_t id = g.boxes[e];
        if (std::find(out, out + n, id) != out + n) continue;
        if (n == cap) return false;
        out[n++] = id;
    }
    return true;
}

}  // namespace

void BoxGrid::build(const std::vector<csg::Aabb>& boxes) {
    first.clear();
    this->boxes.clear();
    if (boxes.empty()) return;
    csg::Aabb all;
    for (const csg::Aabb& b : boxes) all.extend(b);
    const glm::dvec3 extent = all.hi - all.lo;
    std::size_t cells = 1;
    double want[3];
    for (int i = 0; i < 3; ++i) {
        std::vector<double> sizes;
        sizes.reserve(boxes.size());
        for (const csg::Aabb& b : boxes) sizes.push_back(b.hi[i] - b.lo[i]);
        std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(sizes.size() / 2), sizes.end());
        const double median = sizes[sizes.size() / 2];
        want[i] = median > 0 ? std::clamp(kCellsPerBox * extent[i] / median, 1.0, 4096.0) : 4096.0;
        if (!(extent[i] > 0)) want[i] = 1;
    }
    const double budget = std::min(double(kCellsPerItem * boxes.size()), kMaxGridCells);
    const double product = want[0] * want[1] * want[2];
    const double scale = product > budget ? std::cbrt(budget / product) : 1.0;
    for (int i = 0; i < 3; ++i) {
        res[i] = std::max(1, int(want[i] * scale));
        cells *= std::size_t(res[i]);
    }
    if (cells < 8) return;
    lo = all.lo;
    for (int i = 0; i < 3; ++i) {
        last[i] = res[i] - 1;
        cell[i] = extent[i] > 0 ? extent[i] / res[i] : 1.0;
        inv_cell[i] = 1 / cell[i];
    }
    slack = 1e-9 * max_abs(extent) + 1e-13 * std::max(max_abs(all.lo), max_abs(all.hi));
    // Counting pass, then the fill (CSR).
    std::vector<std::uint32_t> count(cells + 1, 0);
    const auto for_cells = [&](const csg::Aabb& b, auto&& visit) {
        int k0[3], k1[3];
        for (int i = 0; i < 3; ++i) {
            k0[i] = cell_of(i, b.lo[i] - slack);
            k1[i] = cell_of(i, b.hi[i] + slack);
        }
        for (int z = k0[2]; z <= k1[2]; ++z)
            for (int y = k0[1]; y <= k1[1]; ++y)
                for (int x = k0[0]; x <= k1[0]; ++x)
                    visit(std::size_t(x) + std::size_t(res[0]) * (std::size_t(y) + std::size_t(res[1]) * std::size_t(z)));
    };
    std::size_t entries = 0;
    for (const csg::Aabb& b : boxes)
        for_cells(b, [&](std::size_t c) {
            ++count[c + 1];
            ++entries;
        });
    if (double(entries) > kMaxPerCell * double(cells)) return;
    for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
    this->boxes.resize(entries);
    std::vector<std::uint32_t> fill(count.begin(), count.end() - 1);
    for (std::uint32_t k = 0; k < boxes.size(); ++k) for_cells(boxes[k], [&](std::size_t c) { this->boxes[fill[c]++] = k; });
    first = std::move(count);
}

int BoxGrid::candidates(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& invd, double t0, double t1,
                        std::uint32_t* out, int cap) const {
    if (!(std::isfinite(t0) && std::isfinite(t1))) return -1;
    const glm::dvec3 p0 = o + t0 * d, p1 = o + t1 * d;
    // (The sums bound the largest magnitudes.)
    const double grow = 0.5 * slack + 1e-12 * (sum_abs(o) + std::max(std::abs(t0), std::abs(t1)) * sum_abs(d));
    int k0[3], k1[3];
    for (int i = 0; i < 3; ++i) {
        k0[i] = cell_of(i, std::min(p0[i], p1[i]) - grow);
        k1[i] = cell_of(i, std::max(p0[i], p1[i]) + grow);
    }
    const int n0 = k1[0] - k0[0] + 1, n1 = k1[1] - k0[1] + 1, n2 = k1[2] - k0[2] + 1;
    if (n0 * n1 > kMaxCells || n0 * n1 * n2 > kMaxCells) return -1;  // (each factor <= 4096: no overflow)
    const std::size_t stride_y = std::size_t(res[0]), stride_z = stride_y * std::size_t(res[1]);
    if (n0 * n1 * n2 == 1) return one_cell(*this, k0, out, cap);  // most queries
    // Per axis, the t-range in which the ray lies in each slab of cells
    // (grown by `grow`; the outer slabs reach on to infinity, as the
    // clamped indices do): a cell is crossed in [t0, t1] where its three
    // ranges overlap there.
    double ta[3][kMaxCells], tb[3][kMaxCells];
    for (int i = 0; i < 3; ++i)
        for (int k = k0[i]; k <= k1[i]; ++k) {
            const double lo_k = k == 0 ? -HUGE_VAL : lo[i] + k * cell[i] - grow;
            const double hi_k = k == res[i] - 1 ? HUGE_VAL : lo[i] + (k + 1) * cell[i] + grow;
            double a = (lo_k - o[i]) * invd[i], b = (hi_k - o[i]) * invd[i];
            if (a > b) std::swap(a, b);
            // A NaN (o in the plane, d parallel to it) keeps the slab.
            ta[i][k - k0[i]] = std::max(t0, a);
            tb[i][k - k0[i]] = std::min(t1, b);
        }
    int n = 0;
    for (int z = 0; z < n2; ++z)
        for (int y = 0; y < n1; ++y) {
            const double ayz = std::max(ta[2][z], ta[1][y]), byz = std::min(tb[2][z], tb[1][y]);
            if (!(ayz <= byz)) continue;
            for (int x = 0; x < n0; ++x) {
                if (!(std::max(ayz, ta[0][x]) <= std::min(byz, tb[0][x]))) continue;
                const std::size_t c = std::size_t(k0[0] + x) + stride_y * std::size_t(k0[1] + y) +
                                      stride_z * std::size_t(k0[2] + z);
                if (!add_cell(*this, c, out, n, cap)) return -1;
            }
        }
    return n;
}

// near(): every cell within r + σ/2 (and the round-off of x) of x: a box
// within r of x per axis overlaps that range, so one of its cells is among
// them. Here the ranges k0..k1 that span more than one cell.
int BoxGrid::near_cells(const int* k0, const int* k1, std::uint32_t* out, int cap, const std::uint32_t*& list) const {
    const int n0 = k1[0] - k0[0] + 1, n1 = k1[1] - k0[1] + 1, n2 = k1[2] - k0[2] + 1;
    if (n0 * n1 > kMaxCells || n0 * n1 * n2 > kMaxCells) return -1;
    list = out;
    int n = 0;
    for (int z = k0[2]; z <= k1[2]; ++z)
        for (int y = k0[1]; y <= k1[1]; ++y)
            for (int xk = k0[0]; xk <= k1[0]; ++xk)
                if (!add_cell(*this, std::size_t(xk) + std::size_t(res[0]) * (std::size_t(y) + std::size_t(res[1]) * std::size_t(z)),
                              out, n, cap))
                    return -1;
    return n;
}

}  // namespace kerf::render

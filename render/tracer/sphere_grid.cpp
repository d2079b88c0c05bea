// The grid of a big bare-sphere crowd (sphere_grid.hpp): its build, and the
// camera and shadow queries that walk it (bare_spheres.hpp's grid_first_hit
// and grid_occluded).
#include "render/tracer/sphere_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_invoke.h>

#include "render/tracer/bare_spheres.hpp"
#include "render/tracer/parallel_build.hpp"

namespace kerf::render {

namespace {

// floor(x) clamped to [0, n - 1]: for x >= 0 the truncation is the floor,
// and x86-64's baseline has no rounding instruction (std::floor is a call).
inline int cell_of(double x, int n) { return int(std::min(std::max(x, 0.0), double(n - 1))); }

}  // namespace

void SphereGrid::build(const csg::Aabb& box, const std::vector<Ball>& balls) {
    *this = SphereGrid{};
    const std::size_t count = balls.size();
    if (count == 0 || box.empty()) return;
    std::vector<double> radii;
    radii.reserve(count);
    for (const Ball& b : balls) {
        if (!(b.r >= 0)) return;
        radii.push_back(b.r);
    }
    std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(count / 2), radii.end());
    const double r_mid = radii[count / 2];
    radii = {};
    const glm::dvec3 ext = box.hi - box.lo;
    if (!(ext.x > 0 && ext.y > 0 && ext.z > 0) || !std::isfinite(ext.x + ext.y + ext.z)) return;
    // About one unit per cell (a flat crowd's thin axis counts as one ball
    // thick), but no smaller than the middle ball's radius: a dense crowd
    // of overlapping balls would list each in dozens of cells.
    const glm::dvec3 e = glm::max(ext, glm::dvec3(2 * r_mid));
    double h0 = std::max(std::cbrt(e.x * e.y * e.z / double(count)), r_mid);
    for (;;) {
        for (int a = 0; a < 3; ++a) n[a] = int(std::clamp(std::lround(ext[a] / h0), 1L, 2048L));
        if (double(n[0]) * n[1] * n[2] <= 4.0 * double(count) + 64) break;
        h0 *= 1.25;
    }
    lo = box.lo;
    h = ext / glm::dvec3(n[0], n[1], n[2]);
    inv_h = 1.0 / h;
    size = ext.x + ext.y + ext.z;
    mag = std::abs(box.lo.x) + std::abs(box.lo.y) + std::abs(box.lo.z) + std::abs(box.hi.x) + std::abs(box.hi.y) +
          std::abs(box.hi.z);
    margin = 1e-3 * std::min({h.x, h.y, h.z}) + 1e-12 * mag;
    // Each unit's cells: those its ball's box, grown by the margin, meets;
    // visit(cell) for each, the cell's index in x, then y, then z order.
    const auto for_cells = [&](const Ball& b, auto&& visit) {
        glm::ivec3 c0, c1;
        for (int a = 0; a < 3; ++a) {
            const double r = b.r + margin;
            c0[a] = cell_of((b.c[a] - r - lo[a]) * inv_h[a], n[a]);
            c1[a] = cell_of((b.c[a] + r - lo[a]) * inv_h[a], n[a]);
        }
        for (int z = c0.z; z <= c1.z; ++z)
            for (int y = c0.y; y <= c1.y; ++y)
                for (int x = c0.x; x <= c1.x; ++x) visit((std::size_t(z) * n[1] + std::size_t(y)) * n[0] + std::size_t(x));
    };
    const std::size_t ncells = std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]);
    // A big crowd in two halves, on two threads when the arena has them:
    // the upper half's balls counted apart, then listed in each cell after
    // the lower half's, so every cell lists its units in index order as one
    // pass would, whatever the thread count.
    const std::uint32_t mid = count >= kParallelBuild ? std::uint32_t(count / 2) : std::uint32_t(count);
    std::vector<std::uint32_t> fill(ncells + 1, 0), upper(mid < count ? ncells + 1 : 0, 0);
    std::uint64_t total_lower = 0, total_upper = 0;
    const auto count_cells = [&](std::uint32_t first, std::uint32_t last, std::vector<std::uint32_t>& to, std::uint64_t& total) {
        for (std::uint32_t i = first; i < last; ++i)
            for_cells(balls[i], [&](std::size_t cell) {
                ++to[cell + 1];
                ++total;
            });
    };
    const auto list_cells = [&](std::uint32_t first, std::uint32_t last, std::vector<std::uint32_t>& at) {
        for (std::uint32_t i = first; i < last; ++i) for_cells(balls[i], [&](std::size_t cell) { items[at[cell]++] = i; });
    };
    if (mid < count)
        tbb::parallel_invoke([&] { count_cells(0, mid, fill, total_lower); },
                             [&] { count_cells(mid, std::uint32_t(count), upper, total_upper); });
    else
        count_cells(0, mid, fill, total_lower);
    const std::uint64_t total = total_lower + total_upper;
    if (total > 64 * std::uint64_t(count) + 4096) return;  // balls far larger than a cell: not this crowd's scheme
    if (total > std::numeric_limits<std::uint32_t>::max()) return;  // (start and fill count in 32 bits)
    if (mid < count) {
        // fill: each cell's start; upper: where the upper half's units of it go.
        for (std::size_t i = 0; i < ncells; ++i) {
            const std::uint32_t lower = fill[i + 1];
            fill[i + 1] = fill[i] + lower + upper[i + 1];
            upper[i] = fill[i] + lower;
        }
    } else {
        for (std::size_t i = 0; i < ncells; ++i) fill[i + 1] += fill[i];
    }
    items.resize(std::size_t(total));
    if (mid < count)
        tbb::parallel_invoke([&] { list_cells(0, mid, fill); }, [&] { list_cells(mid, std::uint32_t(count), upper); });
    else
        list_cells(0, mid, fill);
    // The last half's cursors have stopped at each cell's end, the next
    // cell's start: shifted by one they are `start` (no fresh copy of
    // fill made before the listing: its pages cost more than the shift).
    std::vector<std::uint32_t>& ends = mid < count ? upper : fill;
    std::copy_backward(ends.begin(), ends.begin() + std::ptrdiff_t(ncells), ends.end());
    ends[0] = 0;
    start = std::move(ends);
}

namespace {

// One axis of a walk: the t where the ray leaves its cell across the axis
// (`next`), the plane index of that boundary (`c`: plane lo + c·h), the
// step and the index one past the grid's last plane that way, and the cell
// index's stride for one step.
struct WalkAxis {
    double next, lo, h, o, invd;
    int c, step, end;
    std::ptrdiff_t stride;
};

// The cells a ray crosses from t0 on, in order (3D DDA): visit(first, last)
// gets each cell's units and returns true to stop; the walk also stops at
// the first cell whose exit, less `slack`, lies past `limit` (which the
// visits may lower). Each boundary's t is solved from the ray's origin,
// not accumulated, so its error stays that of one step. The three axes are
// three named locals stepped by their own branch: indexed by an axis
// found at run time they would live in memory (and a glm vector indexed
// so is a switch).
template <class Visit>
[[gnu::always_inline]] inline void walk(const SphereGrid& g, const RayState& st, double t0, double slack, const double& limit,
                                        Visit&& visit) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    std::ptrdiff_t cell = 0;
    const auto axis = [&](int a, std::ptrdiff_t stride) {
        WalkAxis w;
        w.lo = g.lo[a];
        w.h = g.h[a];
        w.o = st.o[a];
        w.invd = st.invd[a];
        const int c = cell_of((w.o + t0 * st.d[a] - w.lo) * g.inv_h[a], g.n[a]);
        // A component so small its reciprocal overflows (denormal) moves the
        // ray by nothing across the grid: parallel, as a zero one (else a
        // start on a cell plane gives 0 * inf = NaN and ends the walk).
        w.step = !(std::abs(w.invd) < kInf) ? 0 : st.d[a] > 0 ? 1 : (st.d[a] < 0 ? -1 : 0);
        const int up = w.step > 0 ? 1 : 0;  // the exit plane is c + 1 going up, c going down
        w.c = c + up;
        w.end = (w.step > 0 ? g.n[a] : -1) + up;
        w.next = w.step == 0 ? kInf : (w.lo + double(w.c) * w.h - w.o) * w.invd;
        cell += c * stride;
        w.stride = stride * w.step;
        return w;
    };
    WalkAxis x = axis(0, 1), y = axis(1, g.n[0]), z = axis(2, std::ptrdiff_t(g.n[0]) * g.n[1]);
    // Across the axis' boundary into the next cell; false: past the limit
    // or out of the grid.
    const auto cross = [&](WalkAxis& w) {
        if (!(w.next - slack <= limit)) return false;  // (inf: no boundary left)
        w.c += w.step;
        if (w.c == w.end) return false;
        cell += w.stride;
        w.next = (w.lo + double(w.c) * w.h - w.o) * w.invd;
        return true;
    };
    const std::uint32_t* start = g.start.data();
    const std::uint32_t* items = g.items.data();
    std::uint64_t walked = 0;
    for (;;) {
        ++walked;
        if (visit(items + start[cell], items + start[cell + 1])) break;
        // The nearest boundary, ties to the later axis.
        const bool on = x.next < y.next ? (x.next < z.next ? cross(x) : cross(z)) : (y.next < z.next ? cross(y) : cross(z));
        if (!on) break;
    }
    st.scratch->counters.grid_cells += walked;
}

}  // namespace

int grid_first_hit(RayState& st, const TraceRay& ray, TraceHit& hit) {
    const CsgTracer::Impl& impl = *st.impl;
    const SphereGrid& g = impl.sphere_grid;
    const double t0 = std::max(ray.tnear, st.enter);
    const double t1 = std::min(ray.tfar, st.leave);
    if (!(t0 <= t1)) return 0;
    if (!g.fits(st.o, st.d, t1)) return -1;
    NearestBare near{ray.tfar};
    // Every unit of a grid crowd has its ball (SphereGrid::build): its test
    // without unit_ball_misses' checks, the ray's terms found once.
    const Ball* balls = impl.top.balls.data();
    const std::uint32_t* nodes = impl.top.items.data();
    const double inv_len2 = st.inv_len * st.inv_len, slack_abs = 4 * st.eps_ray, slack_rel = impl.ball_slack;
    // (Copies: take() writes st, so its fields would be loaded again per unit.)
    const glm::dvec3 o = st.o, d = st.d;
    const double a = ray.tnear;
    walk(g, st, t0, g.margin * st.inv_len, near.best, [&](const std::uint32_t* u, const std::uint32_t* end) {
        for (; u != end; ++u)
            if (!ball_misses(balls[*u], o, d, inv_len2, a, near.best, slack_abs, slack_rel)) near.take(st, *u, nodes[*u], a);
        return false;
    });
    return near.answer(hit);
}

int grid_occluded(RayState& st, const TraceRay& ray, std::uint32_t skip, std::uint32_t& by) {
    const CsgTracer::Impl& impl = *st.impl;
    const SphereGrid& g = impl.sphere_grid;
    const double t0 = std::max(ray.tnear, st.enter);
    const double t1 = std::min(ray.tfar, st.leave);
    if (!(t0 <= t1)) return 0;
    if (!g.fits(st.o, st.d, t1)) return -1;
    bool blocked = false;
    walk(g, st, t0, g.margin * st.inv_len, ray.tfar, [&](const std::uint32_t* u, const std::uint32_t* end) {
        for (; u != end; ++u)
            if (*u != skip && bare_sphere_blocks(st, *u, impl.top.items[*u], ray.tnear, ray.tfar)) {
                by = *u;
                return blocked = true;
            }
        return false;
    });
    return blocked ? 1 : 0;
}

}  // namespace kerf::render

// The image region in 32×32 tiles over a TBB arena's threads. Each tile
// first asks whether all its rays miss the scene (tracer/tile_cull.cpp),
// and a tile that does not asks again of its 8×8 blocks; the pixels of a
// tile or block that does are taken as misses without tracing (`traced` false), and
// get what tracing would give, so a pixel's value never depends on which
// tile it falls in (crops move tile borders).
#pragma once
#include <xmmintrin.h>
#include <pmmintrin.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <mutex>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/camera.hpp"
#include "render/shading.hpp"
#include "render/tracer/stack_depth.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

constexpr int kTile = 32;
// A traced tile is culled again in blocks of 8×8: near the solid's outline
// a tile is mostly background, and a block's test (its corner rays shared
// with its neighbours) costs about as much as two background pixels.
constexpr int kBlock = 8, kBlocks = kTile / kBlock;

// traced[j][i]: whether block (i, j) of the tile [x0, x1) × [y0, y1) has a
// ray that may meet the solid or `also` (else its pixels are background).
// Only pinhole and orthographic cameras' corners bound the rays between
// them; other cameras trace everything. When the tracer culls unit by unit,
// a block asks only of the units its tile's rays may meet (its rays are
// some of the tile's).
inline void cull_blocks(const CameraModel& camera, const CsgTracer& tracer, const csg::Aabb& also, int x0, int y0,
                        int x1, int y1, bool (&traced)[kBlocks][kBlocks]) {
    const int nx = (x1 - x0 + kBlock - 1) / kBlock, ny = (y1 - y0 + kBlock - 1) / kBlock;
    bool all = true;
    // The tile's units, and a block's (per thread: up to thousands).
    static thread_local std::vector<std::uint32_t> tile_units, block_units;
    int ntile = -1;
    if (camera.corners_bound_tiles()) {
        glm::dvec3 co[4], cd[4];  // the tile's corner rays, in order round it
        camera.ray(x0, y0, co[0], cd[0]);
        camera.ray(x1, y0, co[1], cd[1]);
        camera.ray(x1, y1, co[2], cd[2]);
        camera.ray(x0, y1, co[3], cd[3]);
        if (tile_units.size() < tracer.cull_unit_count()) {
            tile_units.resize(tracer.cull_unit_count());
            block_units.resize(tracer.cull_unit_count());
        }
        ntile = tracer.near_units(co, cd, nullptr, 0, tile_units.data());
        all = !((ntile >= 0 ? ntile == 0 : tracer.misses_all(co, cd)) && tile_misses_box(also, co, cd));
    }
    for (int j = 0; j < kBlocks; ++j)
        for (int i = 0; i < kBlocks; ++i) traced[j][i] = all;
    if (!all || !camera.corners_bound_tiles() || (nx == 1 && ny == 1)) return;
    // The grid of block corners' rays, each found once.
    glm::dvec3 go[kBlocks + 1][kBlocks + 1], gd[kBlocks + 1][kBlocks + 1];
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
            camera.ray(std::min(x0 + i * kBlock, x1), std::min(y0 + j * kBlock, y1), go[j][i], gd[j][i]);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const glm::dvec3 o[4] = {go[j][i], go[j][i + 1], go[j + 1][i + 1], go[j + 1][i]};
            const glm::dvec3 d[4] = {gd[j][i], gd[j][i + 1], gd[j + 1][i + 1], gd[j + 1][i]};
            const bool misses = ntile >= 0 ? tracer.near_units(o, d, tile_units.data(), ntile, block_units.data()) == 0
                                           : tracer.misses_all(o, d);
            traced[j][i] = !(misses && tile_misses_box(also, o, d));
        }
}

// The default for an untraced run of pixels: each on its own, as traced
// ones are.
template <class Pixel>
struct PixelByPixel {
    Pixel& pixel;
    void operator()(int x0, int x1, int y, ThreadState& ts) const {
        for (int x = x0; x < x1; ++x) pixel(x, y, ts, false);
    }
};

// A pass that takes each row of a block whole, traced or not (for_each_tile).
template <class Row>
struct ByRows {
    Row& row;
};

// The pixels [x0, x1) of row y of a traced block: one by one, or whole (ByRows).
template <class Pixel>
void traced_row(Pixel& pixel, int x0, int x1, int y, ThreadState& ts) {
    for (int x = x0; x < x1; ++x) pixel(x, y, ts, true);
}
template <class Row>
void traced_row(ByRows<Row>& rows, int x0, int x1, int y, ThreadState& ts) {
    rows.row(x0, x1, y, ts, true);
}

// Calls pixel(x, y, thread_state, traced) for every pixel of `region` (or,
// for a ByRows pass, its row(x0, x1, y, thread_state, true) for a row of a
// traced block; for the pixels of a row of a culled block, untraced(x0, x1, y,
// thread_state), which must do what pixel(x, y, ts, false) does for each),
// and progress(fraction) after each tile, serialised; once `*cancel` is set the
// tiles not started are skipped (the caller throws RenderCancelled). A thread with less than
// `stack_need` bytes of stack left traces nothing (stack_depth.hpp); then
// the result is false and the image incomplete. A tile is traced unless
// its rays miss both the solid and the box `also` (where the ground shows a
// shadow, render/ground.hpp; empty: nothing). Not `cull`: every block is
// traced (a pass whose pixels trace next to nothing where all rays miss).
template <class Pixel, class Untraced>
bool for_each_tile(tbb::task_arena& arena, const std::array<int, 4>& region, const CameraModel& camera,
                   const CsgTracer& tracer, const csg::Aabb& also, tbb::enumerable_thread_specific<ThreadState>& states,
                   const std::function<void(double)>& progress, std::size_t stack_need,
                   const std::atomic<bool>* cancel, Pixel&& pixel, Untraced&& untraced, bool cull = true) {
    const int width = region[2] - region[0], height = region[3] - region[1];
    const int tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;
    const int tiles = tiles_x * tiles_y;
    std::mutex progress_mutex;
    int tiles_done = 0;
    std::atomic<bool> short_stack{false};
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& r) {
            if (short_stack.load(std::memory_order_relaxed) || stack_left() < stack_need) {
                short_stack = true;
                return;
            }
            // Denormals only slow the quartic solvers down; every thread uses
            // the same mode, so results stay thread-count independent.
            // The caller's thread may run tiles too: restore its mode after.
            const unsigned saved_ftz = _MM_GET_FLUSH_ZERO_MODE(), saved_daz = _MM_GET_DENORMALS_ZERO_MODE();
            _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
            _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
            ThreadState& ts = states.local();
            for (int tile = r.begin(); tile != r.end(); ++tile) {
                if (cancel && cancel->load(std::memory_order_relaxed)) break;
                const int tx0 = region[0] + (tile % tiles_x) * kTile, ty0 = region[1] + (tile / tiles_x) * kTile;
                const int tx1 = std::min(tx0 + kTile, region[2]), ty1 = std::min(ty0 + kTile, region[3]);
                // Whether the block's pixels are traced, block by block.
                bool traced[kBlocks][kBlocks];
                if (cull) cull_blocks(camera, tracer, also, tx0, ty0, tx1, ty1, traced);
                else std::fill_n(&traced[0][0], kBlocks * kBlocks, true);
                for (int y = ty0; y < ty1; ++y) {
                    const bool* row = traced[(y - ty0) / kBlock];
                    for (int x0 = tx0; x0 < tx1; x0 += kBlock) {
                        const int x1 = std::min(x0 + kBlock, tx1);
                        if (!row[(x0 - tx0) / kBlock]) {
                            untraced(x0, x1, y, ts);
                            continue;
                        }
                        traced_row(pixel, x0, x1, y, ts);
                    }
                }
                if (progress) {
                    std::lock_guard<std::mutex> lock(progress_mutex);
                    progress(double(++tiles_done) / tiles);
                }
            }
            _MM_SET_FLUSH_ZERO_MODE(saved_ftz);
            _MM_SET_DENORMALS_ZERO_MODE(saved_daz);
        });
    });
    return !short_stack;
}

// `progress` for a pass that covers the fractions from..to of the render.
inline std::function<void(double)> progress_part(const std::function<void(double)>& progress, double from, double to) {
    if (!progress) return {};
    return [&progress, from, to](double f) { progress(from + (to - from) * f); };
}

// What every pass of one render shares: for_each_tile's arguments but the
// region, the progress and the pixel.
struct TilePasses {
    tbb::task_arena& arena;
    const CameraModel& camera;
    const CsgTracer& tracer;
    const csg::Aabb& also;
    tbb::enumerable_thread_specific<ThreadState>& states;
    std::size_t stack_need;
    const std::atomic<bool>* cancel;

    template <class Pixel>
    bool run(const std::array<int, 4>& region, const std::function<void(double)>& progress, Pixel&& pixel) const {
        return for_each_tile(arena, region, camera, tracer, also, states, progress, stack_need, cancel, pixel,
                             PixelByPixel<Pixel>{pixel});
    }
    // The same with the untraced runs of culled blocks handed over whole.
    template <class Pixel, class Untraced>
    bool run(const std::array<int, 4>& region, const std::function<void(double)>& progress, Pixel&& pixel,
             Untraced&& untraced) const {
        return for_each_tile(arena, region, camera, tracer, also, states, progress, stack_need, cancel, pixel,
                             untraced);
    }
    // The same with every block's rows handed over whole: row(x0, x1, y,
    // thread_state, traced) for the pixels [x0, x1) of row y. Not `cull`:
    // all of them traced, none culled (traced true), for a pass that
    // traces few rays, so that asking which blocks to cull costs more than
    // the rays it would save (a culled ray gets what tracing gives).
    template <class Row>
    bool run_rows(const std::array<int, 4>& region, const std::function<void(double)>& progress, Row&& row,
                  bool cull = true) const {
        ByRows<Row> rows{row};
        return for_each_tile(arena, region, camera, tracer, also, states, progress, stack_need, cancel, rows,
                             [&row](int x0, int x1, int y, ThreadState& ts) { row(x0, x1, y, ts, false); }, cull);
    }
};

}  // namespace kerf::render

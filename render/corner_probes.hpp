// Adaptive anti-aliasing's corner probes (adaptive_aa.cpp): a candidate pixel
// samples its 4 corners, and each corner is a corner of up to 4 pixels;
// a pixel crossed by one straight edge bisects the 2 sides it crosses, and
// each side is a side of 2 pixels. Neither corner nor side samples have
// jitter, so their values do not depend on which pixel asks; a thread
// keeps the corners and sides of the tile it is tracing (tiles are traced
// start to end on one thread, tiles.hpp) and traces each once per tile.
// Same bytes as tracing them for every pixel, fewer rays.
#pragma once
#include <array>
#include <atomic>
#include <cstdint>

#include <glm/glm.hpp>

#include "render/edge_crossing.hpp"
#include "render/tiles.hpp"
#include "render/tracer/tracer.hpp"

namespace kerf::render {

struct CornerProbe {
    glm::dvec3 color;
    std::uint32_t surface = 0;
    bool on_ground = false;  // ThreadState::on_ground after the sample
    bool traced = false;     // `color`, `surface`, `on_ground` and `look` hold the sample's
    std::uint64_t look = 0;  // what it looks like to the first pass (CentreSamples::look; the ground as a miss)
    double cover = 0;        // what the sample added to the pixel's coverage (--alpha)
    TraceHit hit{-1, {}};    // the solid surface it hit (ThreadState::hit; t < 0: none)
    // The surface's tangent plane at the hit, found once when first asked
    // for (adaptive_aa.cpp): each corner's is asked for by up to 4 sides.
    mutable bool has_plane = false;
    mutable TangentPlane plane;
    // The signed distance from the plane's point to the leaf `across_leaf`
    // (adaptive_aa.cpp, face_model(): the side it lies on), found once:
    // each sample the faces' model answers from this corner asks for it.
    mutable std::uint32_t across_leaf = ~0u;
    mutable double across = 0;
};

// Where the look changes along a side, from its first corner (left or
// top) to its second, found by bisection or predicted from the two
// surfaces' planes and confirmed (adaptive_aa.cpp).
struct SideProbe {
    bool traced = false;
    bool clean = false;  // every sample looked like exactly one of the side's two corners
    double at = 0;       // where the change is, 0..1 from the first corner
    // Located by an exact prediction its one sample confirmed: +1 from the
    // first corner's face, -1 from the second's; 0 otherwise.
    std::int8_t exact = 0;
    glm::dvec3 sum[2];   // the samples that looked like the first, the second corner
    int count[2] = {0, 0};
};

class CornerProbes {
public:
    // A number no earlier render used: a thread's probes from another
    // render (kerf view renders again and again) are never read.
    static std::uint64_t next_generation() {
        static std::atomic<std::uint64_t> counter{0};
        return ++counter;
    }
    // Starts the tile whose top-left pixel is (x0, y0), unless it is the
    // current one. The probes of the tile before are not cleared (200 KB
    // written per tile, a cost of its own on holes_40's 4,096 tiles): each
    // probe's slot keeps the number of the tile it was last handed out in,
    // and a probe from an earlier tile is reset when first asked for. The
    // numbers are kept apart from the probes, 13 KB that stay in cache:
    // beside each probe, the first look at a slot in a tile (most looks: a
    // tile asks for few of its slots, and not for long) waited for memory
    // (perf on holes_40 at 2048² put a quarter of candidate()'s own time
    // on that one load).
    //
    // The tile right of the current one (the next one this thread takes,
    // most often) starts with the probes the two share: the corners on
    // their common border and the sides along it, moved over (they have no
    // jitter: the same values either tile would trace).
    void enter(int x0, int y0, std::uint64_t generation) {
        if (x0 == x0_ && y0 == y0_ && generation == generation_) return;
        const bool right = generation == generation_ && y0 == y0_ && x0 == x0_ + kTile;
        const std::uint32_t before = tile_;
        x0_ = x0, y0_ = y0, generation_ = generation;
        if (++tile_ == 0) {  // the numbers wrapped round: no slot may hold the new one
            corner_tiles_.fill(0), side_tiles_.fill(0);
            tile_ = 1;
            return;
        }
        if (!right || before == 0) return;
        for (std::size_t row = 0; row <= std::size_t(kTile); ++row) {
            const std::size_t from = row * (kTile + 1) + kTile, to = row * (kTile + 1);
            if (corner_tiles_[from] == before) probes_[to] = probes_[from], corner_tiles_[to] = tile_;
            if (row < std::size_t(kTile) && side_tiles_[kCorners + from] == before)
                sides_[kCorners + to] = sides_[kCorners + from], side_tiles_[kCorners + to] = tile_;
        }
    }
    // The corner (cx, cy) of the current tile: x0 <= cx <= x0 + kTile, the same for y.
    CornerProbe& at(int cx, int cy) { return current(probes_, corner_tiles_, index(cx, cy)); }

    // The side from corner (cx, cy) of the current tile to (cx + 1, cy)
    // (horizontal) or to (cx, cy + 1): inside the tile or on its border.
    SideProbe& side(int cx, int cy, bool vertical) {
        return current(sides_, side_tiles_, (vertical ? kCorners : 0) + index(cx, cy));
    }

private:
    template <class Probe, std::size_t N>
    Probe& current(std::array<Probe, N>& probes, std::array<std::uint32_t, N>& tiles, std::size_t i) {
        if (tiles[i] != tile_) probes[i].traced = false, tiles[i] = tile_;
        return probes[i];
    }
    std::size_t index(int cx, int cy) const { return std::size_t((cy - y0_) * (kTile + 1) + (cx - x0_)); }

    static constexpr std::size_t kCorners = (kTile + 1) * (kTile + 1);
    int x0_ = 0, y0_ = 0;
    std::uint64_t generation_ = 0;
    std::uint32_t tile_ = 0;  // the current tile's number on this thread (0: none yet)
    std::array<std::uint32_t, kCorners> corner_tiles_{};  // per slot, the tile it was last handed out in
    std::array<std::uint32_t, 2 * kCorners> side_tiles_{};
    std::array<CornerProbe, kCorners> probes_{};
    std::array<SideProbe, 2 * kCorners> sides_{};  // horizontal, then vertical (a few unused)
};

}  // namespace kerf::render

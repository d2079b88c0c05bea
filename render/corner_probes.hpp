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
};

// Where the look changes along a side, from its first corner (left or
// top) to its second, found by bisection or predicted from the two
// surfaces' planes and confirmed (adaptive_aa.cpp).
struct SideProbe {
    bool traced = false;
    bool clean = false;  // every sample looked like exactly one of the side's two corners
    double at = 0;       // where the change is, 0..1 from the first corner
    glm::dvec3 sum[2];   // the samples that looked like the first, the second corner
    int count[2] = {0, 0};
};

// A probe and the tile (CornerProbes::enter's count) it belongs to.
template <class Probe>
struct Stamped {
    Probe probe;
    std::uint64_t tile = 0;
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
    // probe keeps the number of the tile it was last handed out in, and
    // one from an earlier tile is reset when first asked for.
    void enter(int x0, int y0, std::uint64_t generation) {
        if (x0 == x0_ && y0 == y0_ && generation == generation_) return;
        x0_ = x0, y0_ = y0, generation_ = generation;
        ++tile_;
    }
    // The corner (cx, cy) of the current tile: x0 <= cx <= x0 + kTile, the same for y.
    CornerProbe& at(int cx, int cy) { return current(probes_[index(cx, cy)]); }

    // The side from corner (cx, cy) of the current tile to (cx + 1, cy)
    // (horizontal) or to (cx, cy + 1): inside the tile or on its border.
    SideProbe& side(int cx, int cy, bool vertical) { return current(sides_[(vertical ? kCorners : 0) + index(cx, cy)]); }

private:
    template <class Probe>
    Probe& current(Stamped<Probe>& p) {
        if (p.tile != tile_) p.probe.traced = false, p.tile = tile_;
        return p.probe;
    }
    std::size_t index(int cx, int cy) const { return std::size_t((cy - y0_) * (kTile + 1) + (cx - x0_)); }

    static constexpr std::size_t kCorners = (kTile + 1) * (kTile + 1);
    int x0_ = 0, y0_ = 0;
    std::uint64_t generation_ = 0;
    std::uint64_t tile_ = 0;  // the current tile's number on this thread (0: none yet)
    std::array<Stamped<CornerProbe>, kCorners> probes_{};
    std::array<Stamped<SideProbe>, 2 * kCorners> sides_{};  // horizontal, then vertical (a few unused)
};

}  // namespace kerf::render

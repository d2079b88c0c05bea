// Adaptive anti-aliasing's corner probes (render.cpp): a candidate pixel
// samples its 4 corners, and each corner is a corner of up to 4 pixels.
// A corner sample has no jitter, so its value does not depend on which
// pixel asks; a thread keeps the corners of the tile it is tracing (tiles
// are traced start to end on one thread, tiles.hpp) and traces each once
// per tile. Same bytes as tracing every corner for every pixel, fewer rays.
#pragma once
#include <array>
#include <atomic>
#include <cstdint>

#include <glm/glm.hpp>

#include "render/tiles.hpp"

namespace kerf::render {

struct CornerProbe {
    glm::dvec3 color;
    std::uint32_t surface = 0;
    bool on_ground = false;  // ThreadState::on_ground after the sample
    bool traced = false;
    double cover = 0;        // what the sample added to the pixel's coverage (--alpha)
};

class CornerProbes {
public:
    // A number no earlier render used: a thread's probes from another
    // render (kerf view renders again and again) are never read.
    static std::uint64_t next_generation() {
        static std::atomic<std::uint64_t> counter{0};
        return ++counter;
    }
    // Starts the tile whose top-left pixel is (x0, y0), unless it is the current one.
    void enter(int x0, int y0, std::uint64_t generation) {
        if (x0 == x0_ && y0 == y0_ && generation == generation_) return;
        x0_ = x0, y0_ = y0, generation_ = generation;
        for (CornerProbe& p : probes_) p.traced = false;
    }
    // The corner (cx, cy) of the current tile: x0 <= cx <= x0 + kTile, the same for y.
    CornerProbe& at(int cx, int cy) { return probes_[std::size_t((cy - y0_) * (kTile + 1) + (cx - x0_))]; }

private:
    int x0_ = 0, y0_ = 0;
    std::uint64_t generation_ = 0;
    std::array<CornerProbe, (kTile + 1) * (kTile + 1)> probes_{};
};

}  // namespace kerf::render

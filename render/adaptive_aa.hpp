// Adaptive anti-aliasing's two passes (docs/quality.md), band by band of
// rows: the centre of every pixel of the band and a one-pixel ring
// (adaptive.hpp), then each candidate: the corners next to its unlike
// neighbours, then all 4 (corner_probes.hpp), one straight edge located
// on the sides it crosses (edge_coverage.hpp), or the full pattern of
// RenderOptions::aa_samples.
#pragma once
#include <array>
#include <functional>

#include "render/pixel_sampler.hpp"
#include "render/render.hpp"
#include "render/tiles.hpp"

namespace kerf::render {

// The passes run band by band of this many rows, and only a band's centres
// (and the row either side) are held, not the image's: 8 bytes a pixel,
// at 2048² 34 MB of fresh memory whose first touch cost up to 6 % of
// holes_40's render (kernel page clearing), and out of cache by the time
// the second pass read them.
constexpr int kAaBand = 4 * kTile;

// Renders `region` through `sampler` (which stores the pixels); `progress`
// covers both passes. False when a thread had too little stack (tiles.hpp).
bool render_adaptive(const TilePasses& tiles, const PixelSampler& sampler, const RenderOptions& options,
                     const std::array<int, 4>& region, const std::function<void(double)>& progress);

}  // namespace kerf::render

// Adaptive anti-aliasing's two passes (docs/quality.md): the centre of
// every pixel of the region and a one-pixel ring (adaptive.hpp), then each
// candidate: its 4 corners (corner_probes.hpp), one straight edge located
// on the sides it crosses (edge_coverage.hpp), or the full pattern of
// RenderOptions::aa_samples.
#pragma once
#include <array>
#include <functional>

#include "render/pixel_sampler.hpp"
#include "render/render.hpp"
#include "render/tiles.hpp"

namespace kerf::render {

// Renders `region` through `sampler` (which stores the pixels); `progress`
// covers both passes. False when a thread had too little stack (tiles.hpp).
bool render_adaptive(const TilePasses& tiles, const PixelSampler& sampler, const RenderOptions& options,
                     const std::array<int, 4>& region, const std::function<void(double)>& progress);

}  // namespace kerf::render

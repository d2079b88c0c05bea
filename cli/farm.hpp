// `kerf render --frames N [--frame I]` and `--tile K/N` (docs/farm.md):
// the animation's frames or one band of the image, each file written with
// its render's metadata (farm_key.hpp), and with --resume the files that
// a previous run finished are kept.
#pragma once
#include <string>

#include "cli/options.hpp"

namespace kerf::cli {

// OUT_0001.png ... for frame 1..N (at least 4 digits, more when N needs
// them), the number before the extension.
std::string frame_path(const std::string& output, int frame, int frames);

// OUT_tile03of16.png for band 3 of 16 (K with as many digits as N - 1).
std::string tile_path(const std::string& output, int tile, int tiles);

// Runs the frames or the band o.farm asks for; returns the exit status.
// Every output path is checked before anything is rendered.
int render_farm(const Options& o);

}  // namespace kerf::cli

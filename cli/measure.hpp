// `kerf measure SCENE`: evaluates and lowers the scene like `kerf check`,
// then prints the volume, area, centroid and bounds of its solid
// (render/measure/measure.hpp; docs/spec.md §15).
#pragma once
#include "cli/options.hpp"

namespace kerf::cli {

// Returns the exit status; throws what evaluation throws (main reports it).
int run_measure(const Options& o);

}  // namespace kerf::cli

// The steps of one run from scene file to image file, shared by `kerf
// render` and `kerf watch`; each names its phase on the progress bar.
#pragma once
#include <string>

#include "cli/options.hpp"
#include "cli/progress.hpp"
#include "csg/scene.hpp"
#include "render/render.hpp"

namespace kerf::cli {

// Throws render::ImageWriteError when the output named by `o` cannot be
// written: checked before evaluating, so a typo in -o costs nothing.
void check_output(const Options& o);

// Evaluates the scene (a file, or standard input for "-"), prints its
// warnings and lowers it. Throws what evaluation throws.
csg::Scene evaluate_and_lower(const Options& o, const EvalOptions& eval, ProgressBar& bar);

// Renders `scene` and writes it to `path` atomically.
render::Image render_and_write(const csg::Scene& scene, const render::RenderOptions& ro, const std::string& path,
                               ProgressBar& bar, render::RenderStats* stats = nullptr);

}  // namespace kerf::cli

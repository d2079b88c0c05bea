// The steps of one run from scene file to image file, shared by `kerf
// render` and `kerf watch`; each names its phase on the progress bar.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli/options.hpp"
#include "cli/progress.hpp"
#include "csg/scene.hpp"
#include "render/render.hpp"

namespace kerf::cli {

// The size of the image a render with `ro` writes: its crop, or the whole.
inline std::array<int, 2> output_size(const render::RenderOptions& ro) {
    if (!ro.crop) return {ro.width, ro.height};
    return {(*ro.crop)[2] - (*ro.crop)[0], (*ro.crop)[3] - (*ro.crop)[1]};
}

// Throws render::ImageWriteError when the output named by `o` cannot be
// written: checked before evaluating, so a typo in -o costs nothing.
void check_output(const Options& o);

// The scene text piped in (`-`), read once: named <stdin> in diagnostics;
// includes resolve against `base` (or the working folder) as if the file
// lived there (editors preview unsaved buffers).
std::shared_ptr<const SourceFile> stdin_source(const std::string& base);

// Evaluates the scene (a file, or standard input for "-": `piped` when
// given, so that the farm's frames read it once), prints its warnings and
// lowers it. Throws what evaluation throws. `warnings`: also given them.
csg::Scene evaluate_and_lower(const Options& o, const EvalOptions& eval, ProgressBar& bar,
                              std::shared_ptr<const SourceFile> piped = nullptr,
                              std::vector<Diagnostic>* warnings = nullptr);

// Renders `scene` and writes it to `path` atomically, with PNG text chunks
// `text` (the farm's metadata); `band_row` as write_image()'s (a band).
// `progressive`: the path integrator's image is also written after each
// pass but the last (--progressive). A render that --time-limit stopped
// early says how many paths it has. `rendered`, if given, is called once
// the image is rendered and encoded (write_image()'s `on_encoded`): `scene`
// is not read after it (kerf render frees the scene then, while the file's
// fsyncs wait for the device).
render::Image render_and_write(const csg::Scene& scene, const render::RenderOptions& ro, const std::string& path,
                               ProgressBar& bar, render::RenderStats* stats = nullptr,
                               const std::vector<std::pair<std::string, std::string>>& text = {}, int band_row = -1,
                               bool progressive = false, const std::function<void()>& rendered = {});

}  // namespace kerf::cli

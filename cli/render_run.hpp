// The steps of one `kerf render`, shared by a plain render (main.cpp) and
// the farm's frames and bands (farm.cpp): evaluate and lower with warnings
// printed, render under a progress bar, report statistics.
#pragma once
#include <memory>

#include "cli/options.hpp"
#include "csg/scene.hpp"
#include "grammar/source.hpp"
#include "render/render.hpp"

namespace kerf::cli {

// The scene text piped in (`-`): read once, evaluated as often as needed.
// Named <stdin> in diagnostics; includes resolve against `base` (or the
// working folder) as if the file lived there.
std::shared_ptr<const SourceFile> stdin_source(const std::string& base);

// o.scene (or `piped` when it is "-") evaluated under `eval` and lowered;
// warnings go to standard error. Throws what evaluation throws.
csg::Scene load_scene(const Options& o, const EvalOptions& eval, const std::shared_ptr<const SourceFile>& piped);

// render() with a progress bar named `label`; --stats printed after.
render::Image render_scene(const csg::Scene& scene, const render::RenderOptions& ro, bool stats, const char* label);

}  // namespace kerf::cli

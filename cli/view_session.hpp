// `kerf view SCENE` (docs/spec.md §13, docs/editors.md): the rendering side
// of the live viewer. The HTTP side is cli/view/ (view::Server); this file
// owns the two threads that feed it: one evaluates the scene and watches
// its files (as `kerf watch` does), one renders the newest scene from the
// newest camera, a small preview first and then the full image, dropping
// a render (RenderOptions::cancel) as soon as either changes.
#pragma once
#include "cli/options.hpp"

namespace kerf::cli {

// Prints the URL on standard output and serves until a signal ends the
// process; returns only when it cannot serve (the exit status).
int run_view(const Options& options);

}  // namespace kerf::cli

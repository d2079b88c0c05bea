// `kerf watch SCENE` (= `kerf render --watch`, docs/spec.md §13): render,
// then render again whenever the scene or a file it depends on is saved.
#pragma once
#include "cli/options.hpp"

namespace kerf::cli {

// Runs until a signal ends the process (Ctrl-C); returns only when the
// output cannot be written at all (exit 3) or the files cannot be watched.
int run_watch(const Options& options);

}  // namespace kerf::cli

// What kerf prints when a run fails, and the exit status it means
// (docs/spec.md §8), for `render`/`check`/`dump` (which exit) and `watch`
// (which prints and waits for the next change).
#pragma once
#include <exception>
#include <string>
#include <vector>

#include "grammar/source.hpp"
#include "render/render.hpp"

namespace kerf::cli {

enum Exit { kOk = 0, kSceneError = 1, kUsage = 2, kRenderFailed = 3 };

void print_warnings(const std::vector<Diagnostic>& warnings);

// --stats: rays, time and CSG work per ray of a finished render.
void print_stats(const render::RenderStats& s, const render::Image& img);

// What report_failure prints for `error` (no final newline), and in
// `*status` the exit status it stands for.
std::string describe_failure(const std::exception_ptr& error, int* status);

// Prints `error` on standard error (a located diagnostic, or "kerf: error:
// MESSAGE") and returns the exit status it stands for.
int report_failure(const std::exception_ptr& error);

}  // namespace kerf::cli

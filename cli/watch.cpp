// The watch loop. Each cycle evaluates with EvalOptions::on_dependency
// collecting the files the run read or looked for, watches exactly those,
// writes a preview and then the full image (both atomically, through
// write_image), and waits for the next change, debounced. An interrupted
// write never leaves a partial image or a temporary (render/image's
// replacement removes it on SIGINT/SIGTERM and dies by the signal).
#include "cli/watch.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/file_watcher.hpp"
#include "cli/pipeline.hpp"
#include "cli/report.hpp"
#include "render/image/image.hpp"

namespace kerf::cli {

namespace {

using Clock = std::chrono::steady_clock;

// A save is often several writes (truncate, write, close; or write a copy,
// rename it over): quiet this long means the editor is done.
constexpr int kQuietMs = 100;
constexpr int kLongestMs = 1000;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// One evaluate-and-render. Returns true when a watched file changed before
// the full image was started (then it is not: the next cycle starts over).
bool cycle(const Options& o, FileWatcher& watcher) {
    const auto start = Clock::now();
    std::vector<std::string> deps;
    EvalOptions eval = o.eval;
    eval.on_dependency = [&deps](const std::string& p) { deps.push_back(p); };
    try {
        ProgressBar bar(o.progress);
        csg::Scene scene;
        try {
            scene = evaluate_and_lower(o, eval, bar);
        } catch (...) {
            // What the run read or looked for up to the error (the scene at
            // least): the fix will be saved to one of them.
            watcher.watch(deps);
            throw;
        }
        watcher.watch(deps);

        render::RenderOptions full = o.render;
        full.srgb8 = render::is_8bit_output(o.output);
        // A centre-sample image first unless that is all that was asked.
        const bool two_steps = !full.preview && full.aov == render::Aov::None;
        double preview_s = 0;
        if (two_steps) {
            render::RenderOptions quick = full;
            quick.preview = true;
            quick.adaptive = false;
            quick.spp = 1;
            render_and_write(scene, quick, o.output, bar);
            preview_s = since(start);
            if (watcher.wait(0)) {
                bar.print_above([&] {
                    std::fprintf(stderr, "kerf watch: preview written to %s in %.2f s; a file changed, starting again\n",
                                 o.output.c_str(), preview_s);
                });
                return true;
            }
        }
        render_and_write(scene, full, o.output, bar, nullptr, {}, -1, o.progressive);
        const double total = since(start);
        bar.print_above([&] {
            if (two_steps)
                std::fprintf(stderr, "kerf watch: rendered %s in %.2f s (preview %.2f s)\n", o.output.c_str(), total, preview_s);
            else
                std::fprintf(stderr, "kerf watch: rendered %s in %.2f s\n", o.output.c_str(), total);
        });
    } catch (...) {
        report_failure(std::current_exception());
        std::error_code ec;
        if (std::filesystem::exists(o.output, ec))
            std::fprintf(stderr, "kerf watch: %s keeps the last good image; waiting for a change\n", o.output.c_str());
        else
            std::fprintf(stderr, "kerf watch: nothing written to %s; waiting for a change\n", o.output.c_str());
    }
    return false;
}

}  // namespace

int run_watch(const Options& o) {
    try {
        check_output(o);
    } catch (const render::ImageWriteError& e) {
        std::fprintf(stderr, "kerf: error: %s\n", e.what());
        return kRenderFailed;
    }
    FileWatcher watcher;
    std::fprintf(stderr, "kerf watch: watching %s and what it includes, uses and imports (Ctrl-C stops)\n", o.scene.c_str());
    for (bool changed = cycle(o, watcher);; changed = cycle(o, watcher)) {
        if (!changed) watcher.wait(-1);
        watcher.settle(kQuietMs, kLongestMs);
        // A line that starts each cycle (editors' background task matchers
        // clear the last cycle's problems on it; docs/editors.md).
        std::fprintf(stderr, "kerf watch: %s changed\n", watcher.take_changed().c_str());
    }
}

}  // namespace kerf::cli

// kerf: check, dump, render, watch or view a .sdl scene, or join rendered bands.
// Everything here is argument handling, reporting and exit codes
// (docs/spec.md §7–§8, docs/farm.md); the work is library calls.
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "cli/assemble.hpp"
#include "cli/farm.hpp"
#include "cli/heap_policy.hpp"
#include "cli/measure.hpp"
#include "cli/memory_cap.hpp"
#include "cli/options.hpp"
#include "cli/phase_memory.hpp"
#include "cli/pipeline.hpp"
#include "cli/progress.hpp"
#include "cli/report.hpp"
#include "cli/view_session.hpp"
#include "cli/watch.hpp"
#include "csg/dump.hpp"
#include "render/image/image.hpp"
#include "render/render.hpp"
#include "render/texture.hpp"

namespace {

using namespace kerf;
using namespace kerf::cli;

int run(const Options& o) {
    if (o.command == Command::Watch) return run_watch(o);
    if (o.command == Command::View) return run_view(o);
    if (o.command == Command::Assemble) return assemble(o);
    if (o.command == Command::Measure) return run_measure(o);
    if (o.command == Command::Render && o.farm.any()) return render_farm(o);
    if (o.command == Command::Render) {
        try {
            check_output(o);
        } catch (const render::ImageWriteError& e) {
            std::cerr << "kerf: error: " << e.what() << '\n';
            return kRenderFailed;
        }
    }
    render::RenderStats stats;
    render::Image image;
    PhaseMemory memory;
    // The scene is freed on a thread of its own once the image is encoded,
    // while the file is written and synced: at 2048² spheres_100000's scene
    // is ~30 MB, whose unmapping (~2 ms) otherwise came after the fsyncs,
    // which wait idle for the device. Joined before the memory and time of
    // the write phase are read (on an exception, by the jthread's destructor).
    std::jthread release;
    {
        ProgressBar bar(o.progress, o.stats ? &memory : nullptr);  // erased before anything below prints
        csg::Scene scene = evaluate_and_lower(o, o.eval, bar);
        if (o.command == Command::Check) return kOk;
        if (o.command == Command::Dump) {
            std::cout << csg::dump_scene(scene);
            return kOk;
        }
        render::RenderOptions ro = o.render;
        ro.srgb8 = render::is_8bit_output(o.output);  // colour for an 8-bit file: store its bytes directly
        image = render_and_write(scene, ro, o.output, bar, &stats, {}, -1, o.progressive, [&] {
            try {
                release = std::jthread([](csg::Scene done) { (void)done; }, std::move(scene));
            } catch (...) {
                // No thread to be had: the scene is freed here or at the
                // block's end, and the finished image is still written.
            }
        });
    }
    if (release.joinable()) release.join();
    memory.finish();
    if (o.stats) {
        print_stats(stats, image);
        std::fputs(phase_memory_line(memory).c_str(), stderr);
        std::fputs(phase_time_line(memory).c_str(), stderr);
    }
    return kOk;
}

}  // namespace

int main(int argc, char** argv) {
    Options options;
    try {
        options = parse_options(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const UsageError& e) {
        std::cerr << "kerf: error: " << e.what() << '\n' << usage_text();
        return kUsage;
    }
    if (options.command == Command::Help) {
        std::cout << usage_text();
        return kOk;
    }
    if (options.command == Command::Version) {
        std::cout << "kerf 0.1\n";
        return kOk;
    }
    cap_memory_to_physical();
    if (options.command != Command::Watch && options.command != Command::View) {
        one_heap_for_one_shot();
        options.eval.populate_ahead = true;  // safe on that heap (csg/populate_ahead.hpp)
    }
    csg::set_texture_reader(render::read_texture);  // material(texture = ...) reads images while evaluating
    // -o -: a reader that goes away is a failed write (exit 3, "Broken
    // pipe"), not a signal.
    if (options.output == "-") std::signal(SIGPIPE, SIG_IGN);
    try {
        return run(options);
    } catch (...) {
        return report_failure(std::current_exception());
    }
}

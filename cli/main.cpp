// kerf: check, dump or render a .sdl scene. Everything here is argument
// handling, reporting and exit codes (docs/spec.md §7–§8); the work is library calls.
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/memory_cap.hpp"
#include "cli/options.hpp"
#include "cli/progress.hpp"
#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"
#include "csg/dump.hpp"
#include "render/image/image.hpp"
#include "render/render.hpp"

namespace {

using namespace kerf;

enum Exit { kOk = 0, kSceneError = 1, kUsage = 2, kRenderFailed = 3 };

void print_warnings(const std::vector<Diagnostic>& warnings) {
    for (const auto& w : warnings) std::cerr << format_diagnostic(w) << '\n';
}

void print_stats(const render::RenderStats& s, const render::Image& img) {
    double rays = static_cast<double>(s.primary_rays + s.shadow_rays + s.reflect_rays);
    double per = s.primary_rays + s.shadow_rays + s.reflect_rays > 0 ? 1.0 / rays : 0.0;
    std::fprintf(stderr,
                 "stats: %dx%d, %.0f rays (%llu primary, %llu shadow, %llu reflect)\n"
                 "stats: render %.3f s, %.2f MRay/s\n"
                 "stats: per ray: %.3f union, %.3f difference, %.3f intersection ops, "
                 "%.3f primitive interval tests\n",
                 img.width, img.height, rays, static_cast<unsigned long long>(s.primary_rays),
                 static_cast<unsigned long long>(s.shadow_rays),
                 static_cast<unsigned long long>(s.reflect_rays), s.seconds,
                 s.seconds > 0 ? rays / s.seconds * 1e-6 : 0.0, s.union_ops * per,
                 s.difference_ops * per, s.intersection_ops * per, s.interval_tests * per);
    if (s.refined_pixels > 0)
        std::fprintf(stderr, "stats: anti-aliasing: %llu of %d pixels took the full samples\n",
                     static_cast<unsigned long long>(s.refined_pixels), img.width * img.height);
}

// A scene piped in (editors preview unsaved buffers): named <stdin> in
// diagnostics; includes resolve against `base` (or the working folder) as
// if the file lived there.
std::shared_ptr<const SourceFile> stdin_source(const std::string& base) {
    auto read = read_source_file("/dev/stdin");  // bounded like any scene file
    auto file = std::make_shared<SourceFile>();
    file->path = base.empty() ? "<stdin>" : (std::filesystem::path(base) / "<stdin>").string();
    file->text = read->text;
    return file;
}

int run(const cli::Options& o) {
    if (o.command == cli::Command::Render) {
        try {
            const auto& crop = o.render.crop;  // the image written is the crop
            render::check_output_path(o.output, crop ? (*crop)[2] - (*crop)[0] : o.render.width,
                                      crop ? (*crop)[3] - (*crop)[1] : o.render.height, {o.scene});
        } catch (const render::ImageWriteError& e) {
            std::cerr << "kerf: error: " << e.what() << '\n';
            return kRenderFailed;
        }
    }
    EvalResult evaluated = o.scene == "-" ? evaluate_source(stdin_source(o.base), o.eval) : evaluate_file(o.scene, o.eval);
    print_warnings(evaluated.warnings);
    csg::Scene scene = lower_to_csg(evaluated.graph);
    if (o.command == cli::Command::Check) return kOk;
    if (o.command == cli::Command::Dump) {
        std::cout << csg::dump_scene(scene);
        return kOk;
    }

    render::RenderOptions ro = o.render;
    ro.srgb8 = render::is_8bit_output(o.output);  // colour for an 8-bit file: store its bytes directly

    render::RenderStats stats;
    render::Image image;
    {
        cli::ProgressBar bar("rendering");
        image = render::render(scene, ro, &stats, [&bar](double f) { bar.update(f); });
    }
    try {
        render::write_image(image, o.output);
    } catch (const std::exception& e) {
        std::cerr << "kerf: error: " << e.what() << '\n';
        return kRenderFailed;
    }
    if (o.stats) print_stats(stats, image);
    return kOk;
}

}  // namespace

int main(int argc, char** argv) {
    cli::Options options;
    try {
        options = cli::parse_options(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const cli::UsageError& e) {
        std::cerr << "kerf: error: " << e.what() << '\n' << cli::usage_text();
        return kUsage;
    }
    if (options.command == cli::Command::Help) {
        std::cout << cli::usage_text();
        return kOk;
    }
    if (options.command == cli::Command::Version) {
        std::cout << "kerf 0.1\n";
        return kOk;
    }
    cli::cap_memory_to_physical();
    // -o -: a reader that goes away is a failed write (exit 3, "Broken
    // pipe"), not a signal.
    if (options.output == "-") std::signal(SIGPIPE, SIG_IGN);
    try {
        return run(options);
    } catch (const DefineError& e) {  // a broken -D value is a bad command line
        std::cerr << format_diagnostic(e.diagnostic()) << '\n';
        return kUsage;
    } catch (const SourceError& e) {
        std::cerr << format_diagnostic(e.diagnostic()) << '\n';
        return kSceneError;
    } catch (const IoError& e) {
        std::cerr << "kerf: error: " << e.what() << '\n';
        return kUsage;
    } catch (const std::bad_alloc&) {
        std::cerr << "kerf: error: out of memory\n";
        return kRenderFailed;
    } catch (const std::exception& e) {
        std::cerr << "kerf: error: " << e.what() << '\n';
        return kRenderFailed;
    }
}

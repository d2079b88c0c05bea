// kerf: check, dump or render a .sdl scene, or join rendered bands.
// Everything here is argument handling, reporting and exit codes
// (docs/spec.md §7–§8, docs/farm.md); the work is library calls.
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/assemble.hpp"
#include "cli/farm.hpp"
#include "cli/memory_cap.hpp"
#include "cli/options.hpp"
#include "cli/render_run.hpp"
#include "csg/dump.hpp"
#include "interpreter/interpreter.hpp"
#include "render/image/image.hpp"
#include "render/render.hpp"

namespace {

using namespace kerf;

enum Exit { kOk = 0, kSceneError = 1, kUsage = 2, kRenderFailed = 3 };

int run(const cli::Options& o) {
    if (o.command == cli::Command::Assemble) return cli::assemble(o);
    if (o.command == cli::Command::Render && o.farm.any()) return cli::render_farm(o);
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
    const csg::Scene scene = cli::load_scene(o, o.eval, o.scene == "-" ? cli::stdin_source(o.base) : nullptr);
    if (o.command == cli::Command::Check) return kOk;
    if (o.command == cli::Command::Dump) {
        std::cout << csg::dump_scene(scene);
        return kOk;
    }
    render::RenderOptions ro = o.render;
    ro.srgb8 = render::is_8bit_output(o.output);  // colour for an 8-bit file: store its bytes directly
    const render::Image image = cli::render_scene(scene, ro, o.stats, "rendering");
    try {
        render::write_image(image, o.output);
    } catch (const std::exception& e) {
        std::cerr << "kerf: error: " << e.what() << '\n';
        return kRenderFailed;
    }
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
    } catch (const cli::TileError& e) {  // tiles that do not join: a bad command line
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

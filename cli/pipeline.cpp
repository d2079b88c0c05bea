#include "cli/pipeline.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/report.hpp"
#include "lower/geometry_ops.hpp"
#include "lower/lower.hpp"
#include "render/image/image.hpp"

namespace kerf::cli {

std::shared_ptr<const SourceFile> stdin_source(const std::string& base) {
    auto read = read_source_file("/dev/stdin");  // bounded like any scene file
    auto file = std::make_shared<SourceFile>();
    file->path = base.empty() ? "<stdin>" : (std::filesystem::path(base) / "<stdin>").string();
    file->text = read->text;
    return file;
}

void check_output(const Options& o) {
    const auto [w, h] = output_size(o.render);
    render::check_output_path(o.output, w, h, {o.scene});
}

csg::Scene evaluate_and_lower(const Options& o, const EvalOptions& eval, ProgressBar& bar,
                              std::shared_ptr<const SourceFile> piped, std::vector<Diagnostic>* warnings) {
    bar.phase("evaluate");
    if (o.scene == "-" && !piped) piped = stdin_source(o.base);
    EvalOptions with_ops = eval;  // projection() of a hull needs lowering's resolver (EvalOptions)
    with_ops.resolve_geometry_ops = resolve_geometry_ops;
    EvalResult evaluated = o.scene == "-" ? evaluate_source(piped, with_ops) : evaluate_file(o.scene, with_ops);
    if (!evaluated.warnings.empty()) bar.print_above([&] { print_warnings(evaluated.warnings); });
    if (warnings) *warnings = evaluated.warnings;
    bar.phase("lower");
    SourceLoc main;  // where a warning that the scene is empty points: the main file
    if (!evaluated.graph.nodes.empty()) main.file = evaluated.graph.nodes[evaluated.graph.root].loc.file;
    // The studio camera frames the full image's shape (a crop or a band
    // shows part of the same picture). The graph is given up: lowering
    // frees its nodes as soon as it can. `kerf measure` measures the solid:
    // the ghosts are not lowered at all.
    csg::Scene scene = lower_to_csg(std::move(evaluated.graph),
                                    LowerOptions{o.look, double(o.render.width) / o.render.height,
                                                 o.ghosts && o.command != Command::Measure,
                                                 unsigned(o.render.threads)});
    const bool renders = o.command == Command::Render || o.command == Command::Watch || o.command == Command::View;
    if (scene.root == csg::kNone && renders) {
        // Nothing to draw: the image is the background. OpenSCAD 2021.01
        // writes that PNG silently and refuses an STL ("Current top level
        // object is empty."); kerf renders it and says so (docs/openscad.md,
        // "An empty model"). Located at the main file, as no statement made it.
        Diagnostic empty{Severity::Warning, main,
                         scene.ghosts.empty() ? "the scene has no solid: the image is only its background"
                                              : "the scene has no solid: the image is only its background and its ghosts",
                         1, {}};
        if (eval.werror) {
            empty.severity = Severity::Error;
            empty.message += " [--werror]";
            throw SourceError(empty);
        }
        bar.print_above([&] { print_warnings({empty}); });
        if (warnings) warnings->push_back(std::move(empty));
    }
    return scene;
}

render::Image render_and_write(const csg::Scene& scene, const render::RenderOptions& ro, const std::string& path,
                               ProgressBar& bar, render::RenderStats* stats,
                               const std::vector<std::pair<std::string, std::string>>& text, int band_row,
                               bool progressive, const std::function<void()>& rendered) {
    bar.phase("build");
    render::RenderOptions options = ro;
    if (progressive && ro.integrator == render::Integrator::Path) {
        options.on_pass = [&](const render::Image& image, int paths) {
            if (paths >= ro.spp) return;  // the last pass: written below, once
            render::write_image(image, path, text);
            bar.print_above([&] { std::fprintf(stderr, "kerf: wrote %s (%d of %d paths per pixel)\n", path.c_str(), paths, ro.spp); });
        };
    }
    render::RenderStats own;
    if (!stats) stats = &own;
    render::Image image = render::render(scene, options, stats, [&bar](double f) { bar.update(f); });
    bar.phase("write");
    render::write_image(image, path, text, band_row, rendered);
    if (ro.integrator == render::Integrator::Path && stats->paths_per_pixel < ro.spp && !ro.preview)
        bar.print_above([&] {
            std::fprintf(stderr, "kerf: note: --time-limit %g s reached: %s has %d of %d paths per pixel\n", ro.time_limit,
                         path.c_str(), stats->paths_per_pixel, ro.spp);
        });
    return image;
}

}  // namespace kerf::cli

#include "cli/render_run.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "cli/progress.hpp"
#include "interpreter/interpreter.hpp"
#include "lower/lower.hpp"

namespace kerf::cli {

namespace {

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

}  // namespace

std::shared_ptr<const SourceFile> stdin_source(const std::string& base) {
    auto read = read_source_file("/dev/stdin");  // bounded like any scene file
    auto file = std::make_shared<SourceFile>();
    file->path = base.empty() ? "<stdin>" : (std::filesystem::path(base) / "<stdin>").string();
    file->text = read->text;
    return file;
}

csg::Scene load_scene(const Options& o, const EvalOptions& eval, const std::shared_ptr<const SourceFile>& piped) {
    EvalResult evaluated = o.scene == "-" ? evaluate_source(piped, eval) : evaluate_file(o.scene, eval);
    for (const auto& w : evaluated.warnings) std::cerr << format_diagnostic(w) << '\n';
    return lower_to_csg(evaluated.graph);
}

render::Image render_scene(const csg::Scene& scene, const render::RenderOptions& ro, bool stats, const char* label) {
    render::RenderStats s;
    render::Image image;
    {
        ProgressBar bar(label);
        image = render::render(scene, ro, &s, [&bar](double f) { bar.update(f); });
    }
    if (stats) print_stats(s, image);
    return image;
}

}  // namespace kerf::cli

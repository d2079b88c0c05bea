#include "cli/report.hpp"

#include <cstdio>
#include <iostream>
#include <new>

#include "cli/assemble.hpp"
#include "interpreter/interpreter.hpp"

namespace kerf::cli {

void print_warnings(const std::vector<Diagnostic>& warnings) {
    for (const auto& w : warnings) std::cerr << format_diagnostic(w) << '\n';
}

void print_stats(const render::RenderStats& s, const render::Image& img) {
    double rays = static_cast<double>(s.rays());
    double per = s.rays() > 0 ? 1.0 / rays : 0.0;
    std::fprintf(stderr,
                 "stats: %dx%d, %.0f rays (%llu primary, %llu shadow, %llu reflect, %llu refract)\n"
                 "stats: render %.3f s, %.2f MRay/s\n"
                 "stats: per ray: %.3f union, %.3f difference, %.3f intersection ops, "
                 "%.3f primitive interval tests\n",
                 img.width, img.height, rays, static_cast<unsigned long long>(s.primary_rays),
                 static_cast<unsigned long long>(s.shadow_rays),
                 static_cast<unsigned long long>(s.reflect_rays), static_cast<unsigned long long>(s.refract_rays), s.seconds,
                 s.seconds > 0 ? rays / s.seconds * 1e-6 : 0.0, s.union_ops * per,
                 s.difference_ops * per, s.intersection_ops * per, s.interval_tests * per);
    if (s.refined_pixels > 0 || s.edge_pixels > 0)
        std::fprintf(stderr, "stats: anti-aliasing: %llu of %d pixels took the full samples, %llu a located straight edge\n",
                     static_cast<unsigned long long>(s.refined_pixels), img.width * img.height,
                     static_cast<unsigned long long>(s.edge_pixels));
}

std::string describe_failure(const std::exception_ptr& error, int* status) {
    try {
        std::rethrow_exception(error);
    } catch (const DefineError& e) {  // a broken -D value is a bad command line
        *status = kUsage;
        return format_diagnostic(e.diagnostic());
    } catch (const SourceError& e) {
        *status = kSceneError;
        if (e.reported.empty()) return format_diagnostic(e.diagnostic());
        std::string text;  // several top-level errors of one run, one per line
        for (const Diagnostic& d : e.reported) text += (text.empty() ? "" : "\n") + format_diagnostic(d);
        return text;
    } catch (const IoError& e) {
        *status = kUsage;
        return std::string("kerf: error: ") + e.what();
    } catch (const TileError& e) {  // tiles that do not join: a bad command line
        *status = kUsage;
        return std::string("kerf: error: ") + e.what();
    } catch (const std::bad_alloc&) {
        *status = kRenderFailed;
        return "kerf: error: out of memory";
    } catch (const std::exception& e) {
        *status = kRenderFailed;
        return std::string("kerf: error: ") + e.what();
    }
}

int report_failure(const std::exception_ptr& error) {
    int status = kRenderFailed;
    const std::string text = describe_failure(error, &status);
    std::cerr << text << '\n';
    return status;
}

}  // namespace kerf::cli

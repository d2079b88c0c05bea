#include "cli/measure.hpp"

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "cli/pipeline.hpp"
#include "cli/progress.hpp"
#include "cli/report.hpp"
#include "render/measure/measure.hpp"

namespace kerf::cli {

int run_measure(const Options& o) {
    render::Measurement m;
    {
        ProgressBar bar(o.progress);  // erased before the figures print
        const csg::Scene scene = evaluate_and_lower(o, o.eval, bar);
        bar.phase("measure");
        try {
            m = render::measure(scene, o.measure, [&bar](double f) { bar.update(f); });
        } catch (const std::runtime_error& e) {
            bar.print_above([&] { std::cerr << o.scene << ": error: " << e.what() << '\n'; });
            return kSceneError;
        }
    }
    if (m.empty) {
        std::cerr << o.scene << ": warning: the scene has no solid; its volume and area are 0\n";
        std::printf("volume: 0 ± 0\narea: 0 ± 0\ncentroid: undef\nbounds: undef\n");
        return kOk;
    }
    std::printf("volume: %.9g ± %.2g\n", m.volume, m.volume_error);
    std::printf("area: %.9g ± %.2g\n", m.area, m.area_error);
    std::printf("centroid: [%.9g, %.9g, %.9g]\n", m.centroid.x, m.centroid.y, m.centroid.z);
    std::printf("bounds: [[%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g]]\n", m.bounds.lo.x, m.bounds.lo.y, m.bounds.lo.z,
                m.bounds.hi.x, m.bounds.hi.y, m.bounds.hi.z);
    return kOk;
}

}  // namespace kerf::cli

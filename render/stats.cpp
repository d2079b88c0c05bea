#include "render/stats.hpp"

namespace kerf::render {

RenderStats sum_stats(const tbb::enumerable_thread_specific<ThreadState>& states, double seconds) {
    RenderStats s;
    for (const ThreadState& ts : states) {
        s.primary_rays += ts.rays.primary;
        s.shadow_rays += ts.rays.shadow;
        s.reflect_rays += ts.rays.reflect;
        s.refract_rays += ts.rays.refract;
        s.union_ops += ts.scratch.counters.union_ops;
        s.difference_ops += ts.scratch.counters.difference_ops;
        s.intersection_ops += ts.scratch.counters.intersection_ops;
        s.interval_tests += ts.scratch.counters.interval_tests;
        s.refined_pixels += ts.refined_pixels;
        s.edge_pixels += ts.edge_pixels;
    }
    s.seconds = seconds;
    return s;
}

}  // namespace kerf::render

// CsgTracer::solve_ahead (tracer.hpp): the first leaf of a run of camera
// rays solved in one loop. A sphere's spans are a function of the leaf and
// the ray alone (not of the window), computed here from the same object-
// space ray as analytic_spans computes, so the query that takes them gets
// the same bits.
#include <algorithm>

#include "render/tracer/build.hpp"

namespace kerf::render {

bool CsgTracer::solve_ahead(const TraceRay* rays, int n, AheadSpans* out) const {
    const std::uint32_t leaf_id = impl_->ahead_leaf;
    if (leaf_id == csg::kNone) return false;
    const csg::Leaf& leaf = impl_->scene.leaves[leaf_id];
    constexpr int kChunk = 8;
    for (int k0 = 0; k0 < n; k0 += kChunk) {
        const int m = std::min(kChunk, n - k0);
        glm::dvec3 lo[kChunk], ld[kChunk];
        for (int k = 0; k < m; ++k) {
            const TraceRay& ray = rays[k0 + k];
            lo[k] = impl_->leaf_point(leaf_id, ray.o);
            ld[k] = impl_->leaf_vector(leaf_id, ray.d);
        }
        csg::Span<double> spans[kChunk * csg::kMaxSpans];
        int count[kChunk];
        csg::intersect_sphere_rays(leaf, m, lo, ld, spans, count);
        for (int k = 0; k < m; ++k) {
            AheadSpans& a = out[k0 + k];
            a.leaf = leaf_id;
            a.count = count[k];
            a.o = rays[k0 + k].o;
            a.d = rays[k0 + k].d;
            for (int i = 0; i < count[k]; ++i) a.spans[i] = spans[k * csg::kMaxSpans + i];  // no more are read
        }
    }
    return true;
}

}  // namespace kerf::render

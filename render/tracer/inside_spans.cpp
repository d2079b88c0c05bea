// CsgTracer::inside_spans, for `kerf measure`: every span of the root solid
// along a ray, not only the first entry. The root is a union of units, so the
// answer is the union of each unit's spans (Need::All). The top BVH's
// intersect callback gathers instead of shrinking tfar when ctx.gather is
// set (first_hit.cpp), so every unit the ray crosses is visited.
#include <algorithm>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

void gather_unit(TopContext& ctx, std::uint32_t node) {
    ctx.state->enter_unit(node);
    ctx.state->spans(node, ctx.tnear, ctx.best, Need::All);  // left on the stack
    ctx.gather_eps = std::max(ctx.gather_eps, ctx.state->eps);
}

void CsgTracer::inside_spans(const TraceRay& ray, TraceScratch& scratch, std::vector<Span>& out) const {
    out.clear();
    RayState st;
    if (!make_state(st, impl_.get(), ray, scratch)) return;
    TopContext ctx(st, ray);
    ctx.gather = true;
    SpanStack& stack = scratch.stack;
    const std::uint32_t base = stack.size();
    for (std::uint32_t node : impl_->top.always) gather_unit(ctx, node);
    if (!impl_->top.bvh) {
        for (std::uint32_t node : impl_->top.items) gather_unit(ctx, node);
    } else {
        RTCRayHit rh = make_rayhit(st, ray.tnear, ray.tfar);
        impl_->top.ready();  // (a bare crowd's grid defers it: build.cpp)
        rtcIntersect1(impl_->top.bvh, &ctx.rtc, &rh);
    }
    const int n = span_normalize_union(stack.at(base), int(stack.size() - base), ctx.gather_eps);
    for (int i = 0; i < n; ++i) {
        Span sp = *stack.at(base + std::uint32_t(i));
        sp.t0 = std::max(sp.t0, ray.tnear);
        sp.t1 = std::min(sp.t1, ray.tfar);
        if (sp.t1 > sp.t0) out.push_back(sp);
    }
    stack.resize(base);
}

}  // namespace kerf::render

// CsgTracer::occluded, for shadow rays: does any unit of the root have a
// span of positive length inside (tnear, tfar)? Uses Embree's occlusion
// query and stops at the first unit that blocks (the callback sets
// tfar = -inf); differences stop at their first piece that answers (Need::Any).
#include <algorithm>
#include <limits>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

// `item`: the unit's index in the top BVH (its ball), or kNone.
bool unit_blocks(TopContext& ctx, std::uint32_t item, std::uint32_t node) {
    if (unit_ball_misses(*ctx.state, item, ctx.tnear, ctx.best)) return false;
    TraceScratch& s = *ctx.state->scratch;
    const std::uint32_t base = s.stack.size();
    ctx.state->enter_unit(node);
    const std::uint32_t n = ctx.state->spans(node, ctx.tnear, ctx.best, Need::Any);
    bool blocks = false;
    for (std::uint32_t i = 0; i < n && !blocks; ++i) {
        const Span& sp = *s.stack.at(base + i);
        blocks = std::min(sp.t1, ctx.best) - std::max(sp.t0, ctx.tnear) > ctx.state->eps;
    }
    s.stack.resize(base);
    return blocks;
}

}  // namespace

void top_occluded_callback(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TopContext*>(args->context);
    if (unit_blocks(*ctx, args->primID, ctx->accel->items[args->primID])) {
        ctx->found = true;
        reinterpret_cast<RTCRay*>(args->ray)->tfar = -std::numeric_limits<float>::infinity();
    }
}

bool CsgTracer::occluded(const TraceRay& ray, TraceScratch& scratch) const {
    RayState st;
    if (!make_state(st, impl_.get(), ray, scratch)) return false;
    TopContext ctx(st, ray);
    for (std::uint32_t node : impl_->top.always)
        if (unit_blocks(ctx, csg::kNone, node)) return true;
    if (!impl_->top.bvh) {
        for (std::uint32_t i = 0; i < impl_->top.items.size(); ++i)
            if (unit_blocks(ctx, i, impl_->top.items[i])) return true;
        return false;
    }
    RTCRay r = make_rayhit(st, ray.tnear, ray.tfar).ray;
    rtcOccluded1(impl_->top.bvh, &ctx.rtc, &r);
    return ctx.found;
}

}  // namespace kerf::render

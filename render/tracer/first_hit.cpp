// CsgTracer::intersect: the root solid's first entry (README.md, "Units").
// The root's units get closest-hit semantics in the top BVH: each unit's
// exact first entry shrinks the float ray's tfar, so Embree culls every unit
// behind it. Ties go to the lower unit index, so traversal order never
// changes the result.
#include <algorithm>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

// The unit's first entry in (tnear, best). True if it is the new best.
bool try_unit_entry(TopContext& ctx, std::uint32_t unit_index, std::uint32_t node) {
    if (unit_ball_misses(*ctx.state, unit_index, ctx.tnear, ctx.best)) return false;
    TraceScratch& s = *ctx.state->scratch;
    const std::uint32_t base = s.stack.size();
    ctx.state->enter_unit(node);
    const std::uint32_t n = ctx.state->spans(node, ctx.tnear, ctx.best, Need::First);
    bool better = false;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Span& sp = *s.stack.at(base + i);
        if (sp.t0 <= ctx.tnear) continue;
        if (sp.t0 < ctx.best || (sp.t0 == ctx.best && ctx.found && unit_index < ctx.best_unit)) {
            ctx.best = sp.t0;
            ctx.best_unit = unit_index;
            ctx.best_end = sp.e0;
            ctx.found = better = true;
        }
        break;
    }
    s.stack.resize(base);
    return better;
}

}  // namespace

void top_intersect_callback(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TopContext*>(args->context);
    if (ctx->gather) return gather_unit(*ctx, ctx->accel->items[args->primID]);
    if (try_unit_entry(*ctx, args->primID, ctx->accel->items[args->primID])) {
        RTCRayHit* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
        rh->ray.tfar = std::min(rh->ray.tfar, embree_t(*ctx->state, ctx->best));
        rh->hit.geomID = args->geomID;
        rh->hit.primID = args->primID;
    }
}

bool CsgTracer::intersect(const TraceRay& ray, TraceHit& hit, TraceScratch& scratch) const {
    RayState st;
    if (!make_state(st, impl_.get(), ray, scratch)) return false;
    TopContext ctx(st, ray);
    // Unbounded units (numbered after the BVH's for ties) go first: the
    // traversal then starts with their entry as tfar.
    const std::uint32_t always_offset = std::uint32_t(impl_->top.items.size());
    for (std::size_t i = 0; i < impl_->top.always.size(); ++i)
        try_unit_entry(ctx, always_offset + std::uint32_t(i), impl_->top.always[i]);
    if (!impl_->top.bvh) {
        for (std::size_t i = 0; i < impl_->top.items.size(); ++i)
            try_unit_entry(ctx, std::uint32_t(i), impl_->top.items[i]);
    } else {
        RTCRayHit rh = make_rayhit(st, ray.tnear, ctx.best);
        rtcIntersect1(impl_->top.bvh, &ctx.rtc, &rh);
    }
    if (!ctx.found) return false;
    hit.t = ctx.best;
    hit.surface = ctx.best_end;
    return true;
}

}  // namespace kerf::render

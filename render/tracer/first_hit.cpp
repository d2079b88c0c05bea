// CsgTracer::intersect: the root solid's first entry (README.md, "Units").
// The root's units get closest-hit semantics in the top BVH: each unit's
// exact first entry shrinks the float ray's tfar, so Embree culls every unit
// behind it. Ties go to the lower unit index, so traversal order never
// changes the result. Sphere-minus-few units are first bounded by the
// chords of their balls and evaluated after the traversal, nearest bound
// first (README.md, "Ball chords").
#include <algorithm>
#include <limits>

#include "render/tracer/ball_chords.hpp"
#include "render/tracer/bare_spheres.hpp"

namespace kerf::render {

namespace {

// A unit's first entry past tnear: the new best if it is nearer, or as
// near and the unit comes first (ties go by unit index).
bool take_entry(TopContext& ctx, std::uint32_t unit_index, const Span& sp) {
    if (!(sp.t0 < ctx.best || (sp.t0 == ctx.best && ctx.found && unit_index < ctx.best_unit))) return false;
    ctx.best = sp.t0;
    ctx.best_unit = unit_index;
    ctx.best_end = sp.e0;
    ctx.found = true;
    return true;
}

// The unit's first entry in (tnear, best). True if it is the new best.
// minuend_entry: the ball chords proved that entry to be the minuend's own
// (entry_is_minuends): the difference's box test, then the minuend leaf
// alone, as difference_spans starts, without its subtractions.
bool try_unit_entry(TopContext& ctx, std::uint32_t unit_index, std::uint32_t node, bool minuend_entry = false) {
    RayState& st = *ctx.state;
    if (unit_ball_misses(st, unit_index, ctx.tnear, ctx.best)) return false;
    TraceScratch& s = *st.scratch;
    const std::uint32_t base = s.stack.size();
    st.enter_unit(node);
    std::uint32_t n = 0;
    Span entry;
    int decided;
    if (!minuend_entry && st.impl->grid_minus[node] && (decided = st.grid_first_entry(node, ctx.tnear, ctx.best, entry)) >= 0) {
        // A holed plate's unit, decided in locals (no span stack).
        if (decided == 0 || !(entry.t0 > ctx.tnear)) return false;
        return take_entry(ctx, unit_index, entry);
    }
    if (!minuend_entry) {
        n = st.spans(node, ctx.tnear, ctx.best, Need::First);
    } else if (slab_hit(st.impl->padded[node], st.o, st.invd, ctx.tnear - st.eps, ctx.best + st.eps)) {
        const csg::Scene& scene = st.impl->scene;
        n = st.spans(scene.children[scene.nodes[node].first], ctx.tnear, ctx.best, Need::All);
    }
    bool better = false;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Span& sp = *s.stack.at(base + i);
        if (sp.t0 <= ctx.tnear) continue;
        better = take_entry(ctx, unit_index, sp);
        break;
    }
    s.stack.resize(base);
    return better;
}

// queue_by_chords past the outer chord's test: the rest of the chords, in a
// function of its own so that the test's misses (most callbacks) do not
// pay for this frame.
[[gnu::noinline]] bool queue_reached(TopContext& ctx, std::uint32_t item, std::uint32_t node, double cut,
                                     const ball_chords_detail::Centre& m, double h2, float& tfar) {
    UnitChords u;
    if (!unit_chords(*ctx.state, item, node, ctx.tnear, cut, m, h2, u)) return true;
    const double lower = chords_lower(u, ctx.tnear, cut);
    if (lower == kInf || lower > cut) return true;
    const double upper = chords_upper(*ctx.state, u, ctx.tnear, cut);
    // No upper bound (a subtrahend's box covers the minuend): evaluate it now,
    // so its entry shrinks the ray as before.
    if (upper == kInf) return false;
    if (upper < ctx.ub) {
        ctx.ub = upper;
        tfar = std::min(tfar, embree_t(*ctx.state, upper));
    }
    ctx.candidates[ctx.ncandidates++] = {lower, item, entry_is_minuends(u)};
    return true;
}

// A sphere-minus-few unit (ball_chords.hpp): dropped when its chords prove
// it has no entry before the best so far (or the smallest upper bound),
// else queued with its lower bound; its upper bound shrinks the float ray.
// False when the caller must evaluate it now (no upper bound, or the queue
// is full).
// at: the unit's terms from a camera apex the ray starts at, or null.
[[gnu::always_inline]] inline bool queue_by_chords(TopContext& ctx, std::uint32_t item, std::uint32_t node,
                                                   float& tfar, const Apex::AtP* at) {
    if (ctx.ncandidates == TopContext::kMaxCandidates) return false;
    const double cut = std::min(ctx.best, ctx.ub);
    ball_chords_detail::Centre m;
    double h2;
    if (!(at ? outer_chord_reaches(*ctx.state, *at, ctx.tnear, cut, m, h2)
             : outer_chord_reaches(*ctx.state, item, ctx.tnear, cut, m, h2)))
        return true;
    return queue_reached(ctx, item, node, cut, m, h2, tfar);
}

// The queued units, nearest lower bound first, until the bound passes the
// best entry found: usually the first one is the answer and the rest are
// never evaluated. (Ties go by unit index in try_unit_entry, so the order
// only changes the work.)
void evaluate_queued(TopContext& ctx) {
    TopContext::Candidate* c = ctx.candidates;
    std::sort(c, c + ctx.ncandidates, [](const TopContext::Candidate& x, const TopContext::Candidate& y) {
        return x.lower < y.lower || (x.lower == y.lower && x.item < y.item);
    });
    for (int i = 0; i < ctx.ncandidates; ++i) {
        if (c[i].lower > std::min(ctx.best, ctx.ub)) break;
        try_unit_entry(ctx, c[i].item, ctx.accel->items[c[i].item], c[i].minuend_entry);
    }
}

// One unit the traversal reached: queued by its chords or evaluated now;
// `tfar` (the float ray's) shrinks to what it proves. True if its entry is
// the new best.
[[gnu::always_inline]] inline bool visit_unit(TopContext& ctx, std::uint32_t item, float& tfar,
                                              const Apex::AtP* at = nullptr) {
    const std::vector<SphereMinus>& sm = ctx.accel->sphere_minus;
    const std::uint32_t node = ctx.accel->items[item];
    if (item < sm.size() && sm[item].r_in >= 0 && queue_by_chords(ctx, item, node, tfar, at)) return false;
    if (!try_unit_entry(ctx, item, node)) return false;
    tfar = std::min(tfar, embree_t(*ctx.state, ctx.best));
    return true;
}

// A camera ray in a ray cone (ray_cones.hpp): its units, nearest the camera
// first, until the next one lies wholly past the best entry or upper bound
// (a point of the ray at t is within t·|d| + rho of the apex).
// A ray that starts exactly at the camera takes each unit's terms of the
// outer chord's test from the apex (Apex::at_p).
void visit_cone(TopContext& ctx, const RayCone& cone) {
    const double len = ctx.state->len;
    float tfar = std::numeric_limits<float>::infinity();  // (no Embree ray to shrink)
    const Apex& ap = ctx.state->impl->apexes[cone.apex];
    const Apex::AtP* at = ap.terms_at(ctx.state->o);
    for (const ConeUnit& u : cone.units) {
        if (u.key > std::min(ctx.best, ctx.ub) * len * (1 + 1e-9)) break;
        visit_unit(ctx, u.item, tfar, at ? at + u.j : nullptr);
    }
    if (ctx.ncandidates > 0) evaluate_queued(ctx);
}

}  // namespace

void top_intersect_callback(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TopContext*>(args->context);
    if (ctx->gather) return gather_unit(*ctx, ctx->accel->items[args->primID]);
    RTCRayHit* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    if (visit_unit(*ctx, args->primID, rh->ray.tfar)) {
        rh->hit.geomID = args->geomID;
        rh->hit.primID = args->primID;
    }
}

// The ball BVH's filter: Embree met the unit's ball. The hit is always
// accepted, with tfar set to what the unit proves (Embree keeps an accepted
// filter's tfar and restores the old one on a rejection, which would lose a
// shrink), so the sphere's own t never culls anything.
void top_ball_filter(const RTCFilterFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TopContext*>(const_cast<RTCIntersectContext*>(args->context));
    visit_unit(*ctx, RTCHitN_primID(args->hit, args->N, 0), ctx->tfar);
    RTCRayN_tfar(args->ray, args->N, 0) = ctx->tfar;
}

bool CsgTracer::intersect(const TraceRay& ray, TraceHit& hit, TraceScratch& scratch) const {
    if (impl_->bare_spheres)  // a crowd of bare spheres: its cones' own loop (bare_spheres.hpp)
        if (const int r = bare_first_hit(*impl_, ray, hit, scratch); r >= 0) return r == 1;
    RayState st;
    if (!make_state(st, impl_.get(), ray, scratch)) return false;
    // A holed plate alone (one unit, a grid_minus difference): its entry
    // without the top-level context, as try_unit_entry would take it.
    if (const std::uint32_t unit = impl_->plate_unit; unit != csg::kNone && !unit_ball_misses(st, 0, ray.tnear, ray.tfar)) {
        st.enter_unit(unit);
        Span entry;
        const int decided = st.grid_first_entry(unit, ray.tnear, ray.tfar, entry);
        if (decided == 0) return false;
        if (decided == 1) {
            if (!(entry.t0 > ray.tnear && entry.t0 < ray.tfar)) return false;
            hit.t = entry.t0;
            hit.surface = entry.e0;
            return true;
        }
    }
    TopContext ctx(st, ray);
    // Unbounded units (numbered after the BVH's for ties) go first: the
    // traversal then starts with their entry as tfar.
    const std::uint32_t always_offset = std::uint32_t(impl_->top.items.size());
    for (std::size_t i = 0; i < impl_->top.always.size(); ++i)
        try_unit_entry(ctx, always_offset + std::uint32_t(i), impl_->top.always[i]);
    if (!impl_->top.bvh) {
        for (std::size_t i = 0; i < impl_->top.items.size(); ++i)
            try_unit_entry(ctx, std::uint32_t(i), impl_->top.items[i]);
    } else if (const RayCone* cone = ray_cone(st, ray, true)) {
        visit_cone(ctx, *cone);
    } else {
        // Camera rays from outside go through the units' balls as Embree
        // spheres, the rest through their boxes (the same answer).
        const bool balls = start_before_balls(st, ray.tnear);
        RTCRayHit rh = make_rayhit(st, ray.tnear, ctx.best);
        ctx.tfar = rh.ray.tfar;
        if (!balls) impl_->top.ready();  // (a bare crowd's grid defers it: build.cpp)
        rtcIntersect1(balls ? impl_->ball_bvh : impl_->top.bvh, &ctx.rtc, &rh);
        if (ctx.ncandidates > 0) evaluate_queued(ctx);
    }
    if (!ctx.found) return false;
    hit.t = ctx.best;
    hit.surface = ctx.best_end;
    return true;
}

}  // namespace kerf::render

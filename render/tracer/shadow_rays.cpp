// CsgTracer::occluded, for shadow rays: does any unit of the root have a
// span of positive length inside (tnear, tfar)? Uses Embree's occlusion
// query and stops at the first unit that blocks (the callback sets
// tfar = -inf); differences stop at their first piece that answers (Need::Any).
// Sphere-minus-few units are first decided by the chords of their balls
// (README.md, "Ball chords"). A ray that departs outwards from a convex
// leaf holding its whole unit skips that unit (README.md, "Departure").
#include <algorithm>
#include <cmath>
#include <limits>

#include "render/tracer/ball_chords.hpp"
#include "render/tracer/bare_spheres.hpp"

namespace kerf::render {

namespace {

// Solids that lie wholly behind the tangent plane at any point of their
// surface. (A paraboloid with h < 0 and a hyperboloid's waist are not.)
bool convex_leaf(csg::PrimKind kind) {
    return kind == csg::PrimKind::Sphere || kind == csg::PrimKind::Box || kind == csg::PrimKind::Cylinder ||
           kind == csg::PrimKind::Plane;
}

// Marks the leaves under `node` that hold all of it: the node itself if a
// leaf, a difference's minuend, every operand of an intersection (a union's
// operands each hold only a part of it). The one-span leaves those
// differences subtract get the unit's root node in `hollow_unit` (and their
// own node in `hollow_node`): inside them the unit has nothing.
void mark_holders(const csg::Scene& scene, std::uint32_t node, std::uint32_t unit, std::uint32_t root,
                  CsgTracer::Impl& impl) {
    const csg::Node& n = scene.nodes[node];
    switch (n.op) {
        case csg::Op::Leaf:
            if (convex_leaf(scene.leaves[n.first].kind)) impl.convex_unit[n.first] = unit;
            return;
        case csg::Op::Difference:
            for (std::uint32_t k = 1; k < n.count; ++k) {
                const std::uint32_t c = scene.children[n.first + k];
                const csg::Node& sub = scene.nodes[c];
                if (sub.op != csg::Op::Leaf || !one_span_kind(scene.leaves[sub.first].kind)) continue;
                impl.hollow_unit[sub.first] = root;
                impl.hollow_node[sub.first] = c;
            }
            return mark_holders(scene, scene.children[n.first], unit, root, impl);
        case csg::Op::Intersection:
            for (std::uint32_t k = 0; k < n.count; ++k) mark_holders(scene, scene.children[n.first + k], unit, root, impl);
            return;
        case csg::Op::Union: return;
    }
}

// The cosine below which a departing ray is traced against its own unit
// after all: far above the normal's round-off (~1e-15), so a ray that
// leaves the tangent plane this steeply, from 100 degenerate rules outside
// it (CsgTracer::surface_offset), provably stays outside the convex leaf.
constexpr double kDepartureCos = 1e-6;

// Departure into a subtrahend, proven without its surface: the ray o + t·d
// (invd = 1/d) starts inside the leaf `into` and is still inside it where
// it leaves the padded box of the unit `node` (or at b), both by `margin`
// (world; at least 16 of the unit's degenerate rules), so (the leaf being
// convex) it stays in the leaf, where the unit has nothing, until it has
// left the box, which it never enters again. A hole's wall lit through the
// hole's mouth: no cylinder solved. unit_blocks' own test gives the same
// "no": the leaf's exit, where it starts, lies past the box's exit by the
// margin, so its box test fails.
bool stays_inside(const CsgTracer::Impl& impl, const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& invd,
                  double margin, std::uint32_t into, std::uint32_t node, double a, double b) {
    // (A leaf inside the box, as a fishbowl's hollow: never.)
    if (!impl.hollow_exits[impl.scene.nodes[into].first]) return false;
    double t0 = -kInf, t1 = kInf;
    if (!slab_clip(impl.padded[node], o, invd, t0, t1)) return false;
    const double t = std::min(t1, b);
    return t > a && inside_by(impl, into, o + t * d, margin) && inside_by(impl, into, o + a * d, margin);
}

// `item`: the unit's index in the top BVH (its ball), or kNone.
bool unit_blocks(TopContext& ctx, std::uint32_t item, std::uint32_t node) {
    if (unit_ball_misses(*ctx.state, item, ctx.tnear, ctx.best)) return false;
    TraceScratch& s = *ctx.state->scratch;
    const std::uint32_t base = s.stack.size();
    ctx.state->enter_unit(node);
    // Departure into a subtrahend: the ray starts inside the leaf `into`
    // (its span begins at or before tnear), where this unit has nothing;
    // every piece the full evaluation finds lies outside that span (it
    // subtracts the same numbers: a one-span leaf's ends that lie inside
    // the window are found the same whatever the window, and only its exit
    // is used here), so the window may start where the ray leaves it.
    double a = ctx.tnear;
    if (node == ctx.hollow) {
        const RayState& st = *ctx.state;
        if (stays_inside(*st.impl, st.o, st.d, st.invd, 16 * st.eps * st.len, ctx.into, node, a, ctx.best)) return false;
        if (ctx.state->spans(ctx.into, a, ctx.best, Need::All) == 1 && s.stack.at(base)->t0 <= a)
            a = std::max(a, s.stack.at(base)->t1);
        s.stack.resize(base);
    }
    const std::uint32_t n = ctx.state->spans(node, a, ctx.best, Need::Any);
    bool blocks = false;
    for (std::uint32_t i = 0; i < n && !blocks; ++i) {
        const Span& sp = *s.stack.at(base + i);
        blocks = std::min(sp.t1, ctx.best) - std::max(sp.t0, a) > ctx.state->eps;
    }
    s.stack.resize(base);
    return blocks;
}

// (Past the outer chord's test, which blocks_by_chords makes inline.)
[[gnu::noinline]] int blocks_if_reached(TopContext& ctx, std::uint32_t item, std::uint32_t node,
                                        const ball_chords_detail::Centre& m, double h2) {
    UnitChords u;
    if (!unit_chords(*ctx.state, item, node, ctx.tnear, ctx.best, m, h2, u)) return 0;
    if (chords_lower(u, ctx.tnear, ctx.best) == kInf) return 0;
    unit_chords_upper(*ctx.state, u);
    return chords_inside(u, ctx.tnear, ctx.best) < kInf ? 1 : -1;
}

// A sphere-minus-few unit decided by the chords of its balls
// (ball_chords.hpp): 0 no span in the window, 1 a span longer than the
// degenerate rule in it, -1 not proven (evaluate it).
[[gnu::always_inline]] inline int blocks_by_chords(TopContext& ctx, std::uint32_t item, std::uint32_t node) {
    ball_chords_detail::Centre m;
    double h2;
    if (!outer_chord_reaches(*ctx.state, item, ctx.tnear, ctx.best, m, h2)) return 0;
    return blocks_if_reached(ctx, item, node, m, h2);
}

// Whether unit `item` of the top BVH blocks the shadow ray.
[[gnu::always_inline]] inline bool item_blocks(TopContext& ctx, std::uint32_t item) {
    const std::vector<SphereMinus>& sm = ctx.accel->sphere_minus;
    const std::uint32_t node = ctx.accel->items[item];
    int by_chords = -1;
    if (item < sm.size() && sm[item].r_in >= 0) {
        by_chords = blocks_by_chords(ctx, item, node);
        if (by_chords == 0) return false;
    }
    return by_chords == 1 || unit_blocks(ctx, item, node);
}

}  // namespace

void top_occluded_callback(const RTCOccludedFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TopContext*>(args->context);
    if (args->primID != ctx->skip && item_blocks(*ctx, args->primID)) {
        ctx->found = true;
        reinterpret_cast<RTCRay*>(args->ray)->tfar = -std::numeric_limits<float>::infinity();
    }
}

// The ball BVH's shadow filter. The light lies beyond every ball
// (occluded() checks), so each ball the segment meets is reported by its
// front end or, when the ray starts inside it, its back end; a ball wholly
// ahead is reported again by its back end after its front end is rejected:
// the last few rejected units are remembered (Embree reports a leaf's back
// ends right after its front ends) and dropped at once.
void top_ball_occluded_filter(const RTCFilterFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<TopContext*>(const_cast<RTCIntersectContext*>(args->context));
    const std::uint32_t item = RTCHitN_primID(args->hit, args->N, 0);
    if (item == ctx->skip) {
        args->valid[0] = 0;
        return;
    }
    for (std::uint32_t k = 0; k < std::min(ctx->nrejected, TopContext::kRejected); ++k)
        if (ctx->rejected[k] == item) {
            args->valid[0] = 0;
            return;
        }
    if (!item_blocks(*ctx, item)) {
        ctx->rejected[ctx->nrejected++ % TopContext::kRejected] = item;
        args->valid[0] = 0;
        return;
    }
    ctx->found = true;
}

void CsgTracer::Impl::find_convex_units() {
    convex_unit.assign(scene.leaves.size(), csg::kNone);
    hollow_unit.assign(scene.leaves.size(), csg::kNone);
    hollow_node.assign(scene.leaves.size(), csg::kNone);
    // A leaf referenced by more than one node holds none: its hit does not
    // say which unit it came from.
    std::vector<std::uint32_t> refs(scene.leaves.size(), 0);
    for (const csg::Node& n : scene.nodes)
        if (n.op == csg::Op::Leaf) ++refs[n.first];
    const std::uint32_t nitems = std::uint32_t(top.items.size());
    for (std::uint32_t i = 0; i < nitems + top.always.size(); ++i) {
        const std::uint32_t root = i < nitems ? top.items[i] : top.always[i - nitems];
        mark_holders(scene, root, i, root, *this);
    }
    for (std::size_t leaf = 0; leaf < refs.size(); ++leaf)
        if (refs[leaf] != 1) convex_unit[leaf] = hollow_unit[leaf] = hollow_node[leaf] = csg::kNone;
    hollow_exits.assign(scene.leaves.size(), 0);
    for (std::size_t leaf = 0; leaf < refs.size(); ++leaf) {
        if (hollow_unit[leaf] == csg::kNone) continue;
        const csg::Aabb &box = padded[hollow_unit[leaf]], &b = scene.leaves[leaf].bounds;
        hollow_exits[leaf] = !(box.lo.x <= b.lo.x && box.lo.y <= b.lo.y && box.lo.z <= b.lo.z && b.hi.x <= box.hi.x &&
                               b.hi.y <= box.hi.y && b.hi.z <= box.hi.z);
    }
}

Departure CsgTracer::departure(const TraceHit& hit, const glm::dvec3& outward) const {
    const std::uint32_t leaf = hit.surface.leaf;
    if (hit.surface.flip) return {csg::kNone, outward, impl_->hollow_unit[leaf], impl_->hollow_node[leaf]};
    return {impl_->convex_unit[leaf], outward};
}

namespace {

// occluded() past its early answers: out of line, so that a bare crowd's
// rays (most of a lattice's), answered by its own query, do not pay for
// this one's frame.
[[gnu::noinline]] bool occluded_general(const CsgTracer::Impl& impl, const TraceRay& ray, TraceScratch& scratch,
                                        const Departure* from, bool departs) {
    const std::uint32_t nitems = std::uint32_t(impl.top.items.size());
    RayState st;
    if (!make_state(st, &impl, ray, scratch)) return false;
    TopContext ctx(st, ray);
    if (departs) ctx.skip = from->unit;
    if (from) {
        ctx.hollow = from->hollow;
        ctx.into = from->into;
    }
    for (std::uint32_t i = 0; i < impl.top.always.size(); ++i)
        if (nitems + i != ctx.skip && unit_blocks(ctx, csg::kNone, impl.top.always[i])) return true;
    if (!impl.top.bvh) {
        for (std::uint32_t i = 0; i < nitems; ++i)
            if (i != ctx.skip && unit_blocks(ctx, i, impl.top.items[i])) return true;
        return false;
    }
    // A shadow ray to a point light in a ray cone (ray_cones.hpp): its units,
    // nearest the light first, until the next one lies wholly beyond the
    // segment's start (a point of it is within (tfar - t)·|d| + rho of the light).
    if (const RayCone* cone = ray_cone(st, ray, false)) {
        const double seg = (ray.tfar - ray.tnear) * st.len * (1 + 1e-9);
        for (const ConeUnit& u : cone->units) {
            if (u.key > seg) break;
            if (u.item != ctx.skip && item_blocks(ctx, u.item)) return true;
        }
        return false;
    }
    // Through the units' balls when they are Embree spheres and the segment
    // ends outside every ball (a light beyond the crowd), else through their
    // boxes.
    const bool balls = ball_slack_fits(st) && st.leave + ball_margin(st) <= ray.tfar;
    RTCRay r = make_rayhit(st, ray.tnear, ray.tfar).ray;
    if (!balls) impl.top.ready();  // (a bare crowd's grid defers it: build.cpp)
    rtcOccluded1(balls ? impl.ball_bvh : impl.top.bvh, &ctx.rtc, &r);
    return ctx.found;
}

}  // namespace

bool CsgTracer::occluded(const TraceRay& ray, TraceScratch& scratch, const Departure* from) const {
    // The unit the ray departs from, when it leaves steeply enough: it lies
    // behind the convex leaf's tangent plane, the ray starts in front of it
    // and moves away (t >= tnear >= 0), so that unit has no span here.
    const bool departs = from && ray.tnear >= 0 && glm::dot(from->outward, ray.d) > kDepartureCos * glm::length(ray.d);
    // A one-unit scene (a grooved sphere, a lens) whose unit the ray departs
    // from: nothing is left to block it, so no set-up at all.
    const bool lone = impl_->lone_unit != csg::kNone;
    if (departs && lone && from->unit == 0) return false;
    // A one-unit scene whose hole the ray departs into (a holed plate's
    // wall): stays_inside before any set-up, with a margin from a bound on
    // |o| (its 1-norm) instead of the unit's degenerate rule per unit of t.
    if (from && lone && from->hollow == impl_->lone_unit && ray.tnear >= 0) {
        const std::uint32_t node = from->hollow;
        const double margin =
            16 * (impl_->node_eps[node] + impl_->eps_per_distance * (std::abs(ray.o.x) + std::abs(ray.o.y) + std::abs(ray.o.z)));
        if (stays_inside(*impl_, ray.o, ray.d, 1.0 / ray.d, margin, from->into, node, ray.tnear, ray.tfar)) return false;
    }
    // A crowd of bare spheres (no unit is a hollow): its own queries
    // (bare_spheres.hpp).
    if (impl_->bare_spheres && !(from && from->hollow != csg::kNone))
        if (const int r = bare_occluded(*impl_, ray, scratch, departs ? from->unit : csg::kNone); r >= 0) return r == 1;
    return occluded_general(*impl_, ray, scratch, from, departs);
}

}  // namespace kerf::render

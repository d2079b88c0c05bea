// Per-ray state of the tracer. One RayState lives on the stack of each
// intersect/occluded call; the Embree contexts that carry it through nested
// BVH queries start with an RTCIntersectContext (Embree hands that pointer
// back to our callbacks). The per-ray work is spread over several files (node
// spans, difference first entry, mesh leaves, first hit, shadow rays);
// what they share on the hot path is here, inline: no virtual calls, no heap
// allocation, no locks per ray.
#pragma once
#include <cassert>
#include <algorithm>
#include <cstdint>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "render/tracer/tracer.hpp"
#include "render/tracer/float_round.hpp"
#include "render/tracer/span_list.hpp"
#include "render/tracer/build.hpp"

namespace kerf::render {

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Need : std::uint8_t {
    All,    // every span overlapping the window
    First,  // a list whose first span with t0 > a is the true first entry
    Any,    // at least one span overlapping the window, if there is one
};

// Outcome of RayState::first_piece_if_clear.
enum class FastPath : std::uint8_t {
    Unknown,  // not proven: gather every subtrahend
    Found,    // the answering piece is written at `base`
    Past,     // this minuend span starts past the window, and so do later ones
    None,     // this minuend span has no answer
};

// The clearance fast path's probe on a minuend span [t0, t1] (README.md,
// "Tracer design"): for First the span's entry, for Any the middle of its
// part in [a, b], with [t0, t1] narrowed to the sliver of eps round it (a
// sliver longer than eps answers Any). Unknown when no probe proves
// anything (First: the span starts inside the window; Any: its part there
// is too short), Past when it starts past the window, else Found. (The
// ends, not the Span: a 16-byte copy of a span just written field by field
// stalls on store forwarding.)
// Whether a part [q0, q1] of a piece has a middle to probe whose sliver of
// eps either side lies inside it. A part that runs to infinity (a
// half-space's, on a shadow ray to a directional light) has none: its
// middle is at infinity, clear of everything, and the sliver [inf, inf]
// has no length, so a proof there would let the light through.
inline bool probe_fits(double q0, double q1, double eps) {
    return q1 - q0 > 2 * eps && q1 < kInf;
}

inline FastPath fast_path_probe(double& t0, double& t1, double a, double b, Need need, double eps, double& probe) {
    if (need == Need::First) {
        if (!(t0 > a)) return FastPath::Unknown;  // starts inside the minuend: the entry is later
        if (t0 > b) return FastPath::Past;
        probe = t0;
        return FastPath::Found;
    }
    const double p0 = std::max(a, t0), p1 = std::min(b, t1);
    if (!probe_fits(p0, p1, eps)) return FastPath::Unknown;
    probe = 0.5 * (p0 + p1);
    t0 = probe - eps;
    t1 = probe + eps;
    return FastPath::Found;
}

// At most this many subtrahends near the probe are intersected by the fast
// paths (the small differences', leaf_minus's, the subtrahend grid's); more:
// gather them all. One constant for every buffer sized by it: a class-scope
// twin (4) once hid this one (2) inside RayState's own members, so
// near_subtrahends filled four entries into leaf_minus's arrays of two.
constexpr std::uint32_t kMaxNear = 4;

// The squared distance from x to the box (0 inside). Empty boxes (lo =
// +inf) give +inf: an empty solid is far from everything.
// Per axis std::max(0.0, std::max(lo - x, x - hi)), squared and summed in
// axis order. x and y go in one SSE2 register: GCC left a data-dependent
// branch per axis (is the point beyond this slab?), which mispredicts on
// the fast path's probes; maxpd(b, a) is std::max(a, b) for every input,
// NaN included, so the sum is the same bits.
inline double box_distance2(const csg::Aabb& box, const glm::dvec3& x) {
#if defined(__SSE2__)
    const __m128d p = _mm_loadu_pd(&x.x), zero = _mm_setzero_pd();
    const __m128d out = _mm_max_pd(_mm_max_pd(_mm_sub_pd(p, _mm_loadu_pd(&box.hi.x)),
                                              _mm_sub_pd(_mm_loadu_pd(&box.lo.x), p)),
                                   zero);
    const __m128d out_z = _mm_max_sd(_mm_max_sd(_mm_set_sd(x.z - box.hi.z), _mm_set_sd(box.lo.z - x.z)), zero);
    const __m128d sq = _mm_mul_pd(out, out);
    const double z = _mm_cvtsd_f64(out_z);
    return (_mm_cvtsd_f64(sq) + _mm_cvtsd_f64(_mm_unpackhi_pd(sq, sq))) + z * z;
#else
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
        const double out = std::max(0.0, std::max(box.lo[i] - x[i], x[i] - box.hi[i]));
        sum += out * out;
    }
    return sum;
#endif
}

// clearance.cpp: true if x lies inside the leaf `node` (a sphere, box,
// cylinder or frustum) farther than `margin` (world) from its surface;
// false if not, or not known.
bool inside_by(const CsgTracer::Impl& impl, std::uint32_t node, const glm::dvec3& x, double margin);

struct RayState {
    const CsgTracer::Impl* impl;
    glm::dvec3 o, d, invd;
    float org[3], dir[3];
    double len;       // |d|: world length per unit of t
    double inv_len;
    double eps;       // t-length of the degenerate rule in the current unit
    double eps_ray;   // world part of eps from the origin's own magnitude
    double t_pad;     // t slack of float Embree windows
    double t_shift;   // the float Embree ray starts at o + t_shift·d (its t is t - t_shift)
    double enter, leave;  // where the line enters and leaves `reach` (±inf: reach is everything)
    bool float_ray;       // org, dir, t_pad and t_shift are set (float_ray_now)
    TraceScratch* scratch;

    // Sets the degenerate rule for a query of `unit` (tolerances.cpp).
    void enter_unit(std::uint32_t unit) { eps = (impl->node_eps[unit] + eps_ray) * inv_len; }
    // node_spans.cpp: pushes the node's spans overlapping [a, b] and returns
    // their count. Starts with the node's own box test.
    std::uint32_t spans(std::uint32_t node, double a, double b, Need need);
    // node_spans.cpp: pushes the spans of every node of `accel` the ray
    // crosses on [a, b] (unsorted, possibly overlapping): those its grid
    // lists there when it has one and the window is short, else through its BVH.
    void collect(const Accel& accel, double a, double b);
    // The grid's candidates for [a, b] (nodes of `accel`, a superset of
    // those whose padded box the ray crosses there: spans' own box test
    // widens the window by eps), or -1: no grid, or ask the BVH.
    static constexpr int kGridCandidates = 32;
    int grid_candidates(const Accel& accel, double a, double b, std::uint32_t* out) const {
        if (accel.grid.empty()) return -1;
        return accel.grid.candidates(o, d, invd, a - eps, b + eps, out, kGridCandidates);
    }
    // node_spans.cpp: collect with the grid's candidates already found.
    void collect_candidates(const Accel& accel, const std::uint32_t* cand, int n, double a, double b);
    // True if x is provably outside the node and farther than `margin`
    // (world) from it; false if inside, near, or not known. The node's box
    // first, here, inline: most calls end there (a groove far from the
    // entry point), and the full test's call costs more than the box.
    bool clear_of(std::uint32_t node, const glm::dvec3& x, double margin) const {
        if (box_distance2(impl->scene.nodes[node].bounds, x) > margin * margin) return true;
        return clear_of_within_box(node, x, margin);
    }
    // Whether x is clear of every one of the nsub subtrahends subs[] but the
    // near ones (`near`: ascending indices into subs), as clear_of says.
    bool clear_of_all_but(const std::uint32_t* subs, std::uint32_t nsub, const std::uint32_t* near, std::uint32_t nnear,
                          const glm::dvec3& x, double margin) const {
        for (std::uint32_t m = 0, j = 0; m < nsub; ++m) {
            if (j < nnear && near[j] == m) {
                ++j;
                continue;
            }
            if (!clear_of(subs[m], x, margin)) return false;
        }
        return true;
    }
    // The subtrahends subs[] that x is not clear of, as indices into subs
    // (ascending) in near[kMaxNear]; false when there are more.
    bool near_subtrahends(const std::uint32_t* subs, std::uint32_t nsub, const glm::dvec3& x, double margin,
                          std::uint32_t* near, std::uint32_t& nnear) const {
        nnear = 0;
        for (std::uint32_t k = 0; k < nsub; ++k) {
            if (clear_of(subs[k], x, margin)) continue;
            if (nnear == kMaxNear) return false;
            near[nnear++] = k;
        }
        return true;
    }
    // clearance.cpp: clear_of for a point within `margin` of the node's box.
    bool clear_of_within_box(std::uint32_t node, const glm::dvec3& x, double margin) const;
    // difference_fast_path.cpp
    FastPath first_piece_if_clear(const csg::Node& n, std::uint32_t base, std::uint32_t sbase, std::uint32_t i,
                                  double a, double b, Need need);
    FastPath any_piece_if_clear(const csg::Node& n, std::uint32_t base, std::uint32_t sbase, std::uint32_t i,
                                double a, double b, const std::uint32_t* near, std::uint32_t nnear);
    // leaf_minus.cpp: an analytic leaf minus a few analytic leaves
    // (Impl::leaf_minus) for Need::First or Need::Any, in one step.
    std::uint32_t leaf_minus_spans(const csg::Node& n, double a, double b, Need need);
    // mesh_spans.cpp
    std::uint32_t mesh_spans(std::uint32_t leaf_id, double a, double b);
    // difference_first_entry.cpp: a big difference's first entry, and any
    // span (Found, None or Unknown), from the subtrahends near points of the ray.
    std::uint32_t first_entry_by_points(const Accel& subtrahends, std::uint32_t base, std::uint32_t i, double b);
    FastPath any_by_points(const Accel& subtrahends, std::uint32_t base, std::uint32_t sbase, std::uint32_t i,
                           double a, double b);
    // The same first entry of a grid_minus difference `node` on (a, b],
    // for the rays it decides in locals: 1 with the piece in `out`, 0 no
    // entry, -1 not decided (nothing pushed, the counters as they were: ask
    // spans()).
    int grid_first_entry(std::uint32_t node, double a, double b, Span& out);
    // The subtrahends of `accel` within `reach` of x (per axis, by the
    // grid) that are not clear of x by `margin` (at most kMaxNear, node
    // ids); -1: not known.
    int near_subtrahends(const Accel& accel, const glm::dvec3& x, double reach, double margin,
                         std::uint32_t* near) const;
    // Whether x is clear of every subtrahend of `accel` but near[0, nnear)
    // (false: not, or not known).
    bool clear_of_others(const Accel& accel, const std::uint32_t* near, int nnear, const glm::dvec3& x,
                         double margin) const;

    // The spans gathered on the stack from `sbase` up are subtrahends: merges
    // them into their union (left at sbase) and subtracts it from the `nm`
    // minuend spans at index `m` (below sbase). The pieces are written from
    // the returned index on; their count goes to `pieces`.
    std::uint32_t subtract_gathered(std::uint32_t m, std::uint32_t nm, std::uint32_t sbase, int& pieces) {
        SpanStack& st = scratch->stack;
        const int ns = span_normalize_union(st.at(sbase), int(st.size() - sbase), eps);
        const std::uint32_t rbase = sbase + std::uint32_t(ns);
        st.resize(rbase + nm + std::uint32_t(ns));
        pieces = span_difference(st.at(m), int(nm), st.at(sbase), ns, st.at(rbase), eps);
        return rbase;
    }
};

// Whether the ray o + t·d meets `box` for some t in [t0, t1], with invd the
// reciprocal of d per axis. An axis the ray is parallel to has invd = ±inf:
// outside the slab gives ±inf at both ends (an empty range), inside
// -inf..inf; exactly in a face plane gives NaN, which max/min ignore, so the
// box is kept (conservative). [t0, t1] is narrowed to the overlap.
inline bool slab_clip(const csg::Aabb& box, const glm::dvec3& o, const glm::dvec3& invd, double& t0, double& t1) {
    for (int i = 0; i < 3; ++i) {
        double ta = (box.lo[i] - o[i]) * invd[i], tb = (box.hi[i] - o[i]) * invd[i];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

// The same without the clipped window.
inline bool slab_hit(const csg::Aabb& box, const glm::dvec3& o, const glm::dvec3& invd, double t0, double t1) {
    return slab_clip(box, o, invd, t0, t1);
}

// The float Embree ray starts at o + t_shift·d, relative to the frame.
inline void start_float_ray(RayState& st, double t_shift) {
    st.t_shift = t_shift;
    const glm::dvec3 start = st.o + t_shift * st.d - st.impl->frame;
    for (int i = 0; i < 3; ++i) st.org[i] = float(start[i]);
    // (|x|+|y|+|z| >= the length: no square root for a slack.)
    st.t_pad = 1e-5 * (st.impl->frame_radius + std::abs(start.x) + std::abs(start.y) + std::abs(start.z)) * st.inv_len;
}

// The float Embree ray of the state's double ray, started where the line
// enters `reach` (make_state), if not yet set.
inline void float_ray_now(RayState& st) {
    if (st.float_ray) return;
    for (int i = 0; i < 3; ++i) st.dir[i] = float(st.d[i]);
    start_float_ray(st, std::isfinite(st.enter) ? std::max(0.0, st.enter) : 0.0);
    st.float_ray = true;
}

// Sets up `st` for a query along `ray`. Returns false, with the rest of the
// set-up skipped, when the ray's line misses `reach` (the box around every
// bounded unit): a slab test on the whole line (no t-window, so no tolerance
// to get wrong), so background pixels cost three divisions and no more.
// The float ray for Embree starts where the line enters `reach` (or at o if
// that is behind), relative to the BVHs' frame: its rounding then follows
// the scene's extent, not the camera's distance or the scene's offset.
// `embree`: false for a query that never asks Embree (bare_spheres.cpp):
// no float ray even where the scene's queries need one.
[[gnu::always_inline]] inline bool make_state(RayState& st, const CsgTracer::Impl* impl, const TraceRay& ray,
                                              TraceScratch& scratch, bool embree = true) {
    st.invd = 1.0 / ray.d;  // ±inf on axes the ray is parallel to
    double enter = -kInf, leave = kInf;
    if (!slab_clip(impl->reach, ray.o, st.invd, enter, leave)) return false;
    st.impl = impl;
    st.o = ray.o;
    st.d = ray.d;
    st.enter = enter;
    st.leave = leave;
    st.len = glm::length(ray.d);
    st.inv_len = 1 / st.len;
    // (A query through a node's own BVH sets them on first use
    // (float_ray_now); a scene with a BVH of units needs them for every ray.)
    st.float_ray = false;
    if (embree && impl->float_rays) float_ray_now(st);
    // Round-off of t also grows with the origin's own magnitude (far cameras).
    st.eps_ray = impl->eps_per_distance * glm::length(ray.o);
    st.eps = st.eps_ray * st.inv_len;  // until enter_unit
    st.scratch = &scratch;
    return true;
}

// The ball BVH (build.cpp, build_ball_bvh) holds each unit's ball grown by
// a pad; true when the slack the double ball tests add for this ray fits in
// it. ball_margin: 1e-3 of the scene's extent in t, far beyond that pad
// (every ball lies in `reach`, grown by the pad).
inline bool ball_slack_fits(const RayState& st) {
    const CsgTracer::Impl& impl = *st.impl;
    if (!impl.ball_bvh || !std::isfinite(st.enter) || !std::isfinite(st.leave)) return false;
    const glm::dvec3 w = st.o - impl.frame;
    const double w1 = std::abs(w.x) + std::abs(w.y) + std::abs(w.z) + 2 * impl.frame_radius;
    const double slack = 4 * st.eps_ray + impl.ball_slack * w1 + 1e-13 * w1 * w1 / impl.ball_r_min;
    return slack < impl.kBallFloatPad * impl.frame_radius;
}
inline double ball_margin(const RayState& st) { return 1e-3 * st.impl->frame_radius * st.inv_len; }

// Whether a first-hit query may go through the ball BVH: Embree reports a
// sphere only where its chord's front or back end lies on the float ray, so
// a ray that starts inside a ball and ends inside it would never see that
// unit, and the filter, which accepts every ball, needs the front ends.
// True, with the float ray restarted a little before the line enters
// `reach`, when the window starts that early too (camera rays from outside).
inline bool start_before_balls(RayState& st, double tnear) {
    if (!ball_slack_fits(st)) return false;
    const double start = st.enter - ball_margin(st);
    if (!(tnear <= start)) return false;
    start_float_ray(st, start);
    return true;
}

// Whether the unit at index `item` of the top BVH provably has no span on
// [a, b] (its ball, unit_balls.hpp), before any of its evaluation.
inline bool unit_ball_misses(const RayState& st, std::uint32_t item, double a, double b) {
    const std::vector<Ball>& balls = st.impl->top.balls;
    if (item >= balls.size() || balls[item].r < 0) return false;
    return ball_misses(balls[item], st.o, st.d, st.inv_len * st.inv_len, a, b, 4 * st.eps_ray, st.impl->ball_slack);
}

// A float Embree ray over (tnear, tfar) that has hit nothing yet.
inline RTCRayHit embree_ray(float ox, float oy, float oz, float dx, float dy, float dz, float tnear, float tfar) {
    RTCRayHit rh;
    rh.ray.org_x = ox;
    rh.ray.org_y = oy;
    rh.ray.org_z = oz;
    rh.ray.dir_x = dx;
    rh.ray.dir_y = dy;
    rh.ray.dir_z = dz;
    rh.ray.tnear = tnear;
    rh.ray.tfar = tfar;
    rh.ray.time = 0;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

// A t of the double ray as the float Embree ray's t, rounded up, with slack.
inline float embree_t(const RayState& st, double t) {
    assert(st.float_ray);  // made with the ray, or by float_ray_now before the first Embree query
    return round_up(t - st.t_shift) + float(st.t_pad);
}

// The state's ray on the t-window [a, b], widened by t_pad for float round-off.
inline RTCRayHit make_rayhit(const RayState& st, double a, double b) {
    assert(st.float_ray);
    return embree_ray(st.org[0], st.org[1], st.org[2], st.dir[0], st.dir[1], st.dir[2],
                      std::max(0.0f, round_down(a - st.t_shift) - float(st.t_pad)),
                      b == kInf ? std::numeric_limits<float>::infinity() : embree_t(st, b));
}

// A query over the root's units (first_hit.cpp, shadow_rays.cpp).
struct TopContext {
    RTCIntersectContext rtc;  // first member: Embree passes our pointer through
    RayState* state;
    const Accel* accel;
    double tnear;
    double best;              // intersect: current first entry; occluded: tfar
    std::uint32_t best_unit;
    SpanEnd best_end;
    bool found;
    bool gather = false;      // inside_spans: keep every unit's spans on the stack
    double gather_eps = 0;    // inside_spans: the largest degenerate rule met
    std::uint32_t skip = csg::kNone;  // occluded: the unit the ray departs from (Departure)
    std::uint32_t hollow = csg::kNone, into = csg::kNone;  // occluded: Departure::hollow, into
    // intersect: the units the ball chords left open (ball_chords.hpp),
    // evaluated after the traversal in the order of their lower bounds, and
    // `ub`, the smallest upper bound the chords gave (never below the answer).
    struct Candidate {
        double lower;
        std::uint32_t item;
        bool minuend_entry;  // its entry is its minuend's (ball_chords.hpp, entry_is_minuends)
    };
    static constexpr int kMaxCandidates = 32;
    Candidate candidates[kMaxCandidates];
    int ncandidates = 0;
    double ub = kInf;
    float tfar = 0;           // intersect through the ball BVH: the float ray's tfar so far
    // occluded through the ball BVH: the last units found not blocking (the
    // first min(nrejected, kRejected) are set; no set-up for other queries).
    static constexpr std::uint32_t kRejected = 8;
    std::uint32_t rejected[kRejected];
    std::uint32_t nrejected = 0;

    TopContext(RayState& st, const TraceRay& ray)
        : state(&st), accel(&st.impl->top), tnear(ray.tnear), best(ray.tfar), best_unit(0), found(false) {
        rtcInitIntersectContext(&rtc);
    }
};

// ray_cones.cpp: the thread's cone (ray_cones.hpp) holding the ray, when it
// starts at the camera (`from`) or ends at a point light; null otherwise.
const RayCone* ray_cone_of_apex(const RayState& st, const TraceRay& ray, bool from);
inline const RayCone* ray_cone(const RayState& st, const TraceRay& ray, bool from) {
    return st.impl->apexes.empty() ? nullptr : ray_cone_of_apex(st, ray, from);
}

// inside_spans.cpp: pushes every span of the unit `node` on (tnear, best).
void gather_unit(TopContext& ctx, std::uint32_t node);

}  // namespace kerf::render

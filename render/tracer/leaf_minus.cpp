// An analytic leaf minus a few analytic leaves (Impl::leaf_minus: a grooved
// sphere's sphere minus its tori, a shell segment's sphere minus a sphere
// and two boxes), asked for its first entry or any span, in one step. The
// answer and the work are those of difference_spans with its clearance fast
// path (difference_fast_path.cpp): the same windows, box tests, leaf tests,
// span operations and counters in the same order, so the same bits. What
// goes is the span stack between them: the leaves' spans and the pieces
// stay in locals (at most 2 per leaf), the subtrahends are intersected
// without a recursion through RayState::spans each, and only the answer is
// pushed.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "render/tracer/analytic_spans.hpp"

namespace kerf::render {

namespace {

constexpr int kMaxLeafSpans = csg::kMaxSpans;

// Impl::leaf_minus allows at most this many subtrahends (no BVH of their own).
constexpr int kMaxGathered = 8 * kMaxLeafSpans;

// The spans of the near subtrahends (by their index into subs) that the
// fast path intersected on the minuend span's part in the window: when it
// proves nothing, the full subtraction on that same window takes them from
// here instead of intersecting those leaves again (the same calls on the
// same window would give the same bits).
struct NearSpans {
    std::uint32_t count = 0;  // 0: none kept
    std::uint32_t which[kMaxNear];
    int n[kMaxNear];
    SpanBuffer<kMaxNear * kMaxLeafSpans> at;
};

// A leaf's spans (at most kMaxLeafSpans) copied whole, room for all of
// them at both ends, those past the leaf's count included: a copy of fixed
// size is a few vector moves, where std::copy of a count known only at run
// time became `rep movsq`, whose start-up cost ~1 % of the grooved sphere's
// cycles (perf, the copy's samples in leaf_minus_spans).
inline void copy_leaf_spans(const Span* from, Span* to) {
    std::memcpy(static_cast<void*>(to), from, kMaxLeafSpans * sizeof(Span));
}

// Minuend span `m` minus the subtrahend leaves subs[which[j]] (or every
// subtrahend when which is null), each intersected on [wa, wb], in the
// order of subs: the pieces go to out (at most 1 + kMaxGathered), their
// count is returned. With which set, the near spans are kept in `kept`;
// with which null, those already in `kept` are taken from there.
int minus_leaves(RayState& rs, const Span& m, const std::uint32_t* subs, std::uint32_t nsub,
                 const std::uint32_t* which, std::uint32_t nwhich, double wa, double wb, Span* out, NearSpans& kept) {
    SpanBuffer<kMaxGathered> gathered;
    int ng = 0;
    if (which) {
        for (std::uint32_t j = 0; j < nwhich; ++j) {
            Span* to = gathered.at + ng;
            kept.n[j] = analytic_node_spans(rs, subs[which[j]], wa, wb, to);
            kept.which[j] = which[j];
            copy_leaf_spans(to, kept.at.at + j * kMaxLeafSpans);
            ng += kept.n[j];
        }
        kept.count = nwhich;
    } else {
        for (std::uint32_t k = 0, j = 0; k < nsub; ++k) {
            if (j < kept.count && kept.which[j] == k) {
                copy_leaf_spans(kept.at.at + j * kMaxLeafSpans, gathered.at + ng);
                ng += kept.n[j];
                ++j;
                continue;
            }
            ng += analytic_node_spans(rs, subs[k], wa, wb, gathered.at + ng);
        }
    }
    ng = span_normalize_union(gathered.at, ng, rs.eps);
    return span_difference(&m, 1, gathered.at, ng, out, rs.eps);
}

// Whether the ray's segment [p0, p1] lies inside the leaf at `node` with
// `margin` (world) to spare, by convexity: a sphere or box holding both
// ends holds the segment, and so does a torus when one ball of its tube
// (radius r round the core point nearest p0) holds both. Then a minuend's
// part on [p0, p1] minus that leaf is empty, whatever the other
// subtrahends do: a shadow ray leaving a groove through its opening needs
// no torus solve. The margin (twice the degenerate rule) dwarfs the leaf
// test's error, so its spans would have left nothing longer than eps
// either. The object-space margin is the world one times the transform's
// norm bound, as in clearance.cpp. False: not proven.
bool segment_inside(const RayState& rs, std::uint32_t node, double p0, double p1, double margin) {
    const std::uint32_t leaf_id = rs.impl->scene.nodes[node].first;
    const csg::Leaf& leaf = rs.impl->scene.leaves[leaf_id];
    const double m = margin * rs.impl->leaf_stretch[leaf_id];
    const double* c = leaf.p;
    if (leaf.kind != csg::PrimKind::Sphere && leaf.kind != csg::PrimKind::Box && leaf.kind != csg::PrimKind::Torus)
        return false;
    const glm::dvec3 q0 = leaf.object_from_world.point(rs.o + p0 * rs.d);
    const glm::dvec3 q1 = leaf.object_from_world.point(rs.o + p1 * rs.d);
    if (leaf.kind == csg::PrimKind::Box) {
        const glm::dvec3 lo = glm::dvec3(c[0], c[1], c[2]) + m, hi = glm::dvec3(c[3], c[4], c[5]) - m;
        return glm::all(glm::greaterThan(glm::min(q0, q1), lo)) && glm::all(glm::lessThan(glm::max(q0, q1), hi));
    }
    glm::dvec3 centre(0.0);
    double r = c[0] - m;
    if (leaf.kind == csg::PrimKind::Torus) {
        const double rho = std::sqrt(q0.x * q0.x + q0.y * q0.y);
        if (!(rho > 0)) return false;
        centre = glm::dvec3(c[0] * q0.x / rho, c[0] * q0.y / rho, 0.0);
        r = c[1] - m;
    }
    if (!(r > 0)) return false;
    const glm::dvec3 e0 = q0 - centre, e1 = q1 - centre;
    return glm::dot(e0, e0) < r * r && glm::dot(e1, e1) < r * r;
}

// Whether one of the near subtrahends is a torus.
bool any_torus(const RayState& rs, const std::uint32_t* subs, const std::uint32_t* near, std::uint32_t nnear) {
    const csg::Scene& scene = rs.impl->scene;
    for (std::uint32_t j = 0; j < nnear; ++j)
        if (scene.leaves[scene.nodes[subs[near[j]]].first].kind == csg::PrimKind::Torus) return true;
    return false;
}

// first_piece_if_clear and any_piece_if_clear on minuend span m: Found with
// the answer in `answer`, Past, None, or Unknown (gather every subtrahend,
// those intersected here from `kept`: the window of the full subtraction,
// [max(a, m.t0), min(b, m.t1)], is the one used here, as First probes only
// a span that starts inside the window).
FastPath piece_if_clear(RayState& rs, const Span& m, const std::uint32_t* subs, std::uint32_t nsub, double a,
                        double b, Need need, Span& answer, NearSpans& kept) {
    double t0 = m.t0, t1 = m.t1, probe;
    const double eps = rs.eps;
    if (const FastPath p = fast_path_probe(t0, t1, a, b, need, eps, probe); p != FastPath::Found) return p;
    const double margin = 2 * eps * rs.len;
    std::uint32_t near[kMaxNear], nnear;
    if (!rs.near_subtrahends(subs, nsub, rs.o + probe * rs.d, margin, near, nnear)) return FastPath::Unknown;
    if (nnear == 0) {
        answer = m;
        answer.t0 = t0;
        answer.t1 = t1;
        return FastPath::Found;
    }
    SpanBuffer<1 + kMaxNear * kMaxLeafSpans> buffer;
    Span* pieces = buffer.at;
    if (need == Need::First) {
        // Span m minus the near subtrahends, on its part in the window.
        const int r = minus_leaves(rs, m, subs, nsub, near, nnear, probe, std::min(b, m.t1), pieces, kept);
        int k = 0;
        while (k < r && !(pieces[k].t0 > a)) ++k;
        // More subtrahends only shrink the pieces: none here, none at all.
        if (k == r) return FastPath::None;
        if (pieces[k].t0 > b) return FastPath::Past;
        if (!rs.clear_of_all_but(subs, nsub, near, nnear, rs.o + pieces[k].t0 * rs.d, margin)) return FastPath::Unknown;
        answer = pieces[k];
        return FastPath::Found;
    }
    // Any: none when a near subtrahend holds the span's whole part in the
    // window; else the first piece overlapping the window by more than 2·eps
    // whose middle is clear of the others answers with a sliver round it.
    const double p0 = std::max(a, m.t0), p1 = std::min(b, m.t1);
    for (std::uint32_t j = 0; j < nnear; ++j)
        if (segment_inside(rs, subs[near[j]], p0, p1, margin)) return FastPath::None;
    // A second probe just before the part's end, when a near subtrahend is
    // a torus (a quartic: a solve costs several clearance tests): a shadow
    // ray into a groove's far wall runs on through the minuend, and where it
    // leaves it is usually clear of every subtrahend: then [y - 2·eps, p1]
    // is a piece longer than 2·eps, and the near subtrahends need no solve.
    // (The near ones first: a ray leaving through a groove's opening is
    // inside it there.)
    if (const double y = p1 - 2 * eps; y - p0 >= 2 * eps && any_torus(rs, subs, near, nnear)) {
        const glm::dvec3 x = rs.o + y * rs.d;
        bool clear = true;
        for (std::uint32_t j = 0; j < nnear && clear; ++j) clear = rs.clear_of(subs[near[j]], x, margin);
        if (clear && rs.clear_of_all_but(subs, nsub, near, nnear, x, margin)) {
            answer = m;
            answer.t0 = y - eps;
            answer.t1 = y + eps;
            return FastPath::Found;
        }
    }
    const int r = minus_leaves(rs, m, subs, nsub, near, nnear, p0, p1, pieces, kept);
    bool unsure = false;
    for (int k = 0; k < r; ++k) {
        const double q0 = std::max(a, pieces[k].t0), q1 = std::min(b, pieces[k].t1);
        if (!(q1 - q0 > eps)) continue;
        if (!probe_fits(q0, q1, eps)) {
            unsure = true;
            continue;
        }
        const double mid = 0.5 * (q0 + q1);
        if (!rs.clear_of_all_but(subs, nsub, near, nnear, rs.o + mid * rs.d, margin)) return FastPath::Unknown;
        answer = pieces[k];
        answer.t0 = mid - eps;
        answer.t1 = mid + eps;
        return FastPath::Found;
    }
    return unsure ? FastPath::Unknown : FastPath::None;
}

}  // namespace

std::uint32_t RayState::leaf_minus_spans(const csg::Node& n, double a, double b, Need need) {
    scratch->counters.difference_ops++;
    const std::uint32_t* kids = &impl->scene.children[n.first];
    const std::uint32_t* subs = kids + 1;
    const std::uint32_t nsub = n.count - 1;
    SpanBuffer<kMaxLeafSpans> minuend;
    Span* m = minuend.at;
    const int nm = analytic_node_spans(*this, kids[0], a, b, m, scratch->ahead);
    SpanBuffer<1> answer_buffer;
    Span& answer = answer_buffer.at[0];
    for (int i = 0; i < nm; ++i) {
        NearSpans kept;
        const FastPath found = piece_if_clear(*this, m[i], subs, nsub, a, b, need, answer, kept);
        if (found == FastPath::Past) break;
        if (found == FastPath::None) continue;
        if (found == FastPath::Unknown) {
            // Not proven: span i minus every subtrahend on its part in the window.
            SpanBuffer<1 + kMaxGathered> buffer;
            Span* pieces = buffer.at;
            const int r = minus_leaves(*this, m[i], subs, nsub, nullptr, 0, std::max(a, m[i].t0), std::min(b, m[i].t1),
                                       pieces, kept);
            int k = 0;
            for (; k < r; ++k) {
                const Span& p = pieces[k];
                if (need == Need::First ? p.t0 > a && p.t0 <= b : std::min(p.t1, b) - std::max(p.t0, a) > eps) break;
            }
            if (k == r) continue;
            answer = pieces[k];
        }
        scratch->stack.push(answer);
        return 1;
    }
    return 0;
}

}  // namespace kerf::render

// The first entry (and, for shadow rays, any span) of a difference with
// many subtrahends (its own BVH and grid), found without gathering every
// subtrahend along the minuend's chord: "which subtrahends cover the point
// c?", growing the window only while c stays covered. A ray through a slab
// with N holes so costs about log N, not N (README.md, "Tracer design";
// bench/render_models holesN). Where the grid (box_grid.hpp) names the few
// subtrahends near the points that decide, only those are intersected; the
// rest are proven clear of those points (clearance.cpp), so the answer is
// the one gathering them all gives.
#include <algorithm>

#include "render/tracer/analytic_spans.hpp"
#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

bool listed(const std::uint32_t* near, int nnear, std::uint32_t node) {
    return std::find(near, near + nnear, node) != near + nnear;
}

// A leaf whose spans do not depend on the window (only the torus clips to
// it) and that is convex: its one span, found on a window, is what any
// wider window that still overlaps it would give.
bool one_span_leaf(const csg::Scene& scene, std::uint32_t node) {
    const csg::Node& n = scene.nodes[node];
    return n.op == csg::Op::Leaf && one_span_kind(scene.leaves[n.first].kind);
}

// f(node) for every subtrahend the grid names within `reach` of x, those it
// holds outside the grid (`always`) first; false when there is no grid
// answer (no grid, too many) or f says stop.
template <class F>
bool each_near(const Accel& accel, const glm::dvec3& x, double reach, F&& f) {
    if (accel.grid.empty()) return false;
    std::uint32_t cand[RayState::kGridCandidates];
    const std::uint32_t* list;
    const int ncand = accel.grid.near(x, reach, cand, RayState::kGridCandidates, list);
    if (ncand < 0) return false;
    for (std::uint32_t node : accel.always)
        if (!f(node)) return false;
    for (int k = 0; k < ncand; ++k)
        if (!f(list[k])) return false;
    return true;
}

}  // namespace

int RayState::near_subtrahends(const Accel& accel, const glm::dvec3& x, double reach, double margin,
                               std::uint32_t* near) const {
    int nnear = 0;
    const bool all = each_near(accel, x, reach, [&](std::uint32_t node) {
        if (clear_of(node, x, margin)) return true;
        if (nnear == kMaxNear) return false;
        near[nnear++] = node;
        return true;
    });
    return all ? nnear : -1;
}

bool RayState::clear_of_others(const Accel& accel, const std::uint32_t* near, int nnear, const glm::dvec3& x,
                               double margin) const {
    return each_near(accel, x, margin,
                     [&](std::uint32_t node) { return listed(near, nnear, node) || clear_of(node, x, margin); });
}

// Minuend span i lies at base + i (spans after base + count are scratch).
// Returns 1 with the entry written at base, 0 if this minuend span has no
// entry, 2 if the search passed the window's end.
//
// Spans gathered on a window are only true inside it (a composite
// subtrahend's far end may still be uncut), so only crossings strictly
// inside the current window [c, end] are trusted. The window starts as the
// point c (most rays: "is the minuend's entry covered?"), then grows to the
// covering spans' claimed exit, then doubles, until it decides.
//
// With the grid, the first window gathers only the subtrahends near c (not
// clear of it by 3·eps: the others have no span reaching into it, so the
// window's answer and its claimed exit are the same); none near: c is the
// entry. A later window that answers with only those is trusted when its
// entry is clear of every other subtrahend by 2·eps (they cannot cut the
// piece there, nor start an earlier one: more subtrahends only shrink the
// pieces); otherwise that window is gathered in full, as are all after it
// (their claimed exit needs every subtrahend). The answer's far end may
// differ from the full gather's: callers of First read only the entry.
std::uint32_t RayState::first_entry_by_points(const Accel& subtrahends, std::uint32_t base, std::uint32_t i,
                                               double b) {
    SpanStack& st = scratch->stack;
    const std::uint32_t sbase = st.size();
    const Span rest = *st.at(base + i);
    const double c = rest.t0;
    const double stop = std::min(b, rest.t1) + 2 * eps;  // nothing past this matters
    double end = c + 2 * eps;
    std::uint32_t near[kMaxNear];
    // (Within 4·eps·len of c: every subtrahend whose box the first window's
    // gather crosses, as its box test widens [c - 2·eps, c + 2·eps] by eps,
    // with room for that test's round-off.)
    const int nnear = near_subtrahends(subtrahends, o + c * d, 4 * eps * len, 3 * eps * len, near);
    // Most rays: the entry is clear of every subtrahend. (A span no longer
    // than eps is no piece: the gather's subtraction drops it, so the loop
    // below decides that one.)
    if (nnear == 0 && rest.t1 - rest.t0 > eps) {
        if (c > b) return 2;
        st.resize(base + 1);
        *st.at(base) = rest;
        return 1;
    }
    bool all = nnear < 0;
    // A near convex leaf's span from the first window, for the later ones
    // (they all start at c - 2·eps and only grow): the same numbers
    // without solving its surface again.
    Span kept[kMaxNear];
    bool keep[kMaxNear] = {};
    int r = 0;
    std::uint32_t rbase = sbase;
    bool same = false;  // this window gathers what the last one did: its pieces stand
    for (bool first = true;;) {
        if (!same) {
            st.resize(sbase);
            if (all)
                collect(subtrahends, c - 2 * eps, end);
            else
                for (int k = 0; k < nnear; ++k) {
                    if (keep[k]) {
                        st.push(kept[k]);
                        continue;
                    }
                    const std::uint32_t at = st.size();
                    if (spans(near[k], c - 2 * eps, end, Need::All) == 1 && first && one_span_leaf(impl->scene, near[k])) {
                        kept[k] = *st.at(at);
                        keep[k] = true;
                    }
                }
            rbase = subtract_gathered(base + i, 1, sbase, r);
        }
        double claimed = end;  // where the gathered spans say coverage from c ends
        for (std::uint32_t k = sbase; k < rbase; ++k) claimed = std::max(claimed, st.at(k)->t1);
        if (r > 0 && (st.at(rbase)->t0 == c || st.at(rbase)->t0 < end - eps)) {
            const Span piece = *st.at(rbase);
            if (!all && !clear_of_others(subtrahends, near, nnear, o + piece.t0 * d, 2 * eps * len)) {
                all = true;  // the same window with every subtrahend
                same = false;
                continue;
            }
            st.resize(sbase);
            if (piece.t0 > b) return 2;
            *st.at(base) = piece;
            st.resize(base + 1);
            return 1;
        }
        if (end >= stop) {  // the window covered everything that matters: no entry
            st.resize(sbase);
            return rest.t1 + 2 * eps > stop ? 2 : 0;
        }
        if (!all && !first) {  // the next window needs every subtrahend's claimed exit
            all = true;
            same = false;
            continue;
        }
        // Every near subtrahend kept (the second window, near ones only):
        // the same spans from the same minuend span, so the same union and
        // pieces; only the window's end, which decides trust, moves.
        same = !all && std::all_of(keep, keep + nnear, [](bool k) { return k; });
        first = false;
        end = std::min(stop, std::max(claimed + 2 * eps, c + 2 * (end - c)));
    }
}

// first_entry_by_points for a grid_minus difference (the minuend's one
// span m) in locals: the same box tests, spans, unions and subtractions in
// the same order, so the same numbers, for the rays that the first two
// windows of the near subtrahends decide (the entry clear of every
// subtrahend, or the exit of the hole the ray enters). The rest (a near one
// that is not a one-span leaf or that the first window does not meet, a
// piece not clear of the others, a third window) give -1 with the counters
// restored, and spans() starts over.
int RayState::grid_first_entry(std::uint32_t node, double a, double b, Span& out) {
    const csg::Scene& scene = impl->scene;
    const csg::Node& n = scene.nodes[node];
    if (!box_hit(*this, impl->padded[node], a, b)) return 0;
    const TraceCounters before = scratch->counters;
    const auto undecided = [&] {
        scratch->counters = before;
        return -1;
    };
    scratch->counters.difference_ops++;
    SpanBuffer<csg::kMaxSpans> minuend;
    const int nm = analytic_node_spans(*this, scene.children[n.first], a, b, minuend.at);
    if (nm == 0) return 0;
    const Span& m = minuend.at[0];
    const double c = m.t0;
    if (nm > 1) return undecided();
    if (!(c > a)) return undecided();  // starts inside the window: difference_spans gathers
    const Accel& subtrahends = *impl->node_accels[std::size_t(impl->accel_of_node[node])];
    const double stop = std::min(b, m.t1) + 2 * eps;
    double end = c + 2 * eps;
    std::uint32_t near[kMaxNear];
    const int nnear = near_subtrahends(subtrahends, o + c * d, 4 * eps * len, 3 * eps * len, near);
    if (nnear == 0 && m.t1 - m.t0 > eps) {
        if (c > b) return 0;
        out = m;
        return 1;
    }
    if (nnear < 0) return undecided();
    // Each near one's span on the first window, which the second reuses.
    SpanBuffer<kMaxNear * csg::kMaxSpans> gathered;
    Span* u = gathered.at;
    int nu = 0;
    for (int k = 0; k < nnear; ++k) {
        if (!one_span_leaf(scene, near[k])) return undecided();
        if (analytic_node_spans(*this, near[k], c - 2 * eps, end, u + nu) != 1) return undecided();
        ++nu;
    }
    double claimed = end;
    for (int k = 0; k < nu; ++k) claimed = std::max(claimed, u[k].t1);
    nu = span_normalize_union(u, nu, eps);
    SpanBuffer<kMaxNear + 1> left;
    const int r = span_difference(&m, 1, u, nu, left.at, eps);
    for (int window = 0; window < 2; ++window) {
        const Span& piece = left.at[0];
        if (r > 0 && (piece.t0 == c || piece.t0 < end - eps)) {
            if (!clear_of_others(subtrahends, near, nnear, o + piece.t0 * d, 2 * eps * len)) return undecided();
            if (piece.t0 > b) return 0;
            out = piece;
            return 1;
        }
        if (end >= stop) return 0;
        end = std::min(stop, std::max(claimed + 2 * eps, c + 2 * (end - c)));
    }
    return undecided();
}

// Any (a shadow ray) for minuend span i on [a, b]: span i minus the
// subtrahends near a probe; the first piece that overlaps the window by
// more than 2·eps is probed at its middle, and the subtrahends not clear of
// that point join the near ones, until a probe is clear of all others
// (the sliver of eps round it survives them all: Found) or no piece
// overlaps the window by more than eps (more subtrahends only shrink the
// pieces: None). Unknown when it cannot say (too many near, a piece
// between eps and 2·eps, no grid answer): the caller gathers them all.
FastPath RayState::any_by_points(const Accel& subtrahends, std::uint32_t base, std::uint32_t sbase, std::uint32_t i,
                                 double a, double b) {
    SpanStack& st = scratch->stack;
    const double p0 = std::max(a, st.at(base + i)->t0), p1 = std::min(b, st.at(base + i)->t1);
    if (!probe_fits(p0, p1, eps)) return FastPath::Unknown;
    const double margin = 2 * eps * len;
    std::uint32_t near[kMaxNear];
    int nnear = 0;
    st.resize(sbase);
    for (;;) {
        // (Nothing subtracted yet: the span itself is the one piece, as
        // span_difference with no subtrahend spans would give it.)
        int r = 1;
        std::uint32_t rbase = base + i;
        if (nnear > 0)
            rbase = subtract_gathered(base + i, 1, sbase, r);
        else if (!(st.at(base + i)->t1 - st.at(base + i)->t0 > eps))
            r = 0;
        int k = 0;
        double q0 = 0, q1 = 0;
        for (; k < r; ++k) {
            const Span& piece = *st.at(rbase + std::uint32_t(k));
            q0 = std::max(a, piece.t0);
            q1 = std::min(b, piece.t1);
            if (q1 - q0 > eps) break;
        }
        if (k == r) return FastPath::None;
        if (!probe_fits(q0, q1, eps)) return FastPath::Unknown;
        const double probe = 0.5 * (q0 + q1);
        const glm::dvec3 x = o + probe * d;
        // The subtrahends not clear of the probe, not yet subtracted.
        const int before = nnear;
        const bool all = each_near(subtrahends, x, margin, [&](std::uint32_t node) {
            if (listed(near, nnear, node) || clear_of(node, x, margin)) return true;
            if (nnear == kMaxNear) return false;
            near[nnear++] = node;
            return true;
        });
        if (!all) return FastPath::Unknown;
        if (nnear == before) {
            Span sliver = *st.at(rbase + std::uint32_t(k));
            sliver.t0 = probe - eps;
            sliver.t1 = probe + eps;
            *st.at(base) = sliver;
            st.resize(base + 1);
            return FastPath::Found;
        }
        st.resize(before > 0 ? rbase : sbase);  // keep the union so far, drop the pieces
        for (int n = before; n < nnear; ++n) spans(near[n], p0, p1, Need::All);
    }
}

}  // namespace kerf::render

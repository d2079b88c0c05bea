// Windowed spans of the CSG tree (README.md, "Inside a unit"):
// spans(node, a, b) pushes the node's spans that overlap [a, b] onto the
// thread's span stack, correct on that window. Box culling, primitive leaves
// and the union / intersection / difference combinations live in this one
// file because they call each other recursively on the hot path and must
// stay inlinable into each other. Mesh leaves are in mesh_spans.cpp, the
// point-query first entry of big differences in difference_first_entry.cpp,
// the clearance fast path of small ones in difference_fast_path.cpp, an
// analytic leaf minus a few analytic leaves in one step in leaf_minus.cpp.
#include <algorithm>

#include "render/primitives/primitives.hpp"
#include "render/tracer/analytic_spans.hpp"
#include "render/tracer/prism_spans.hpp"
#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

using csg::Node;
using csg::Op;

// A child query over a node's own BVH.
struct CollectContext {
    RTCIntersectContext rtc;  // first member: Embree passes our pointer through
    RayState* state;
    const Accel* accel;
    double a, b;
};

}  // namespace

void collect_callback(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0]) return;
    auto* ctx = reinterpret_cast<CollectContext*>(args->context);
    // Never accepts: every crossed child is gathered, tfar stays.
    ctx->state->spans(ctx->accel->items[args->primID], ctx->a, ctx->b, Need::All);
}

namespace {

// The combinations below are called only from spans (and each other): they
// have internal linkage so the compiler inlines them into it as before the
// split; only spans and collect are reached from other files.

std::uint32_t leaf_spans(RayState& es, const Node& n, double a, double b) {
    const csg::Leaf& leaf = es.impl->scene.leaves[n.first];
    if (leaf.kind == csg::PrimKind::Mesh) return es.mesh_spans(n.first, a, b);
    if (leaf.kind == csg::PrimKind::Prism || leaf.kind == csg::PrimKind::Lathe) return prism_spans(es, n.first, a, b);
    SpanStack& st = es.scratch->stack;
    return std::uint32_t(analytic_spans(es, n.first, a, b, [&st](const Span& s) { st.push(s); }));
}

// A union, intersection or difference (for every span) of exactly two
// analytic leaves (Impl::leaf_pair) in one step: both leaves' spans into
// locals, combined straight onto the stack. The windows, box tests, span
// operations and counters are those of union_spans, intersection_spans and
// difference_spans, so the spans are the same bits; what goes is the two
// recursions through spans, the pushes and the copy back.
std::uint32_t leaf_pair_spans(RayState& es, const Node& n, double a, double b) {
    const std::uint32_t c0 = es.impl->scene.children[n.first], c1 = es.impl->scene.children[n.first + 1];
    SpanStack& st = es.scratch->stack;
    const std::uint32_t base = st.size();
    if (n.op == Op::Union) {
        es.scratch->counters.union_ops++;
        st.resize(base + 2 * csg::kMaxSpans);
        Span* out = st.at(base);
        int count = analytic_node_spans(es, c0, a, b, out);
        count += analytic_node_spans(es, c1, a, b, out + count);
        count = span_normalize_union(out, count, es.eps);
        st.resize(base + std::uint32_t(count));
        return std::uint32_t(count);
    }
    if (n.op == Op::Intersection) es.scratch->counters.intersection_ops++;
    else es.scratch->counters.difference_ops++;
    SpanBuffer<csg::kMaxSpans> xs, ys;
    Span *x = xs.at, *y = ys.at;
    const int nx = analytic_node_spans(es, c0, a, b, x);
    if (nx == 0) return 0;
    // The second operand matters only where the first is inside.
    int ny = analytic_node_spans(es, c1, std::max(a, x[0].t0), std::min(b, x[nx - 1].t1), y);
    int r;
    if (n.op == Op::Intersection) {
        if (ny == 0) return 0;
        st.resize(base + std::uint32_t(nx + ny));
        r = span_intersection(x, nx, y, ny, st.at(base), es.eps);
    } else {
        ny = span_normalize_union(y, ny, es.eps);
        st.resize(base + std::uint32_t(nx + ny));
        r = span_difference(x, nx, y, ny, st.at(base), es.eps);
    }
    st.resize(base + std::uint32_t(r));
    return std::uint32_t(r);
}

// Pushes the spans of children skip.. of an operation node on [a, b]:
// through the node's own BVH if it has one, else child by child.
void collect_children(RayState& es, std::uint32_t node, const Node& n, std::uint32_t skip, double a, double b) {
    const std::int32_t ai = es.impl->accel_of_node[node];
    if (ai >= 0) {
        es.collect(*es.impl->node_accels[std::size_t(ai)], a, b);
        return;
    }
    for (std::uint32_t k = skip; k < n.count; ++k) es.spans(es.impl->scene.children[n.first + k], a, b, Need::All);
}

std::uint32_t union_spans(RayState& es, std::uint32_t node, const Node& n, double a, double b) {
    es.scratch->counters.union_ops++;
    SpanStack& st = es.scratch->stack;
    const std::uint32_t base = st.size();
    collect_children(es, node, n, 0, a, b);
    const int count = span_normalize_union(st.at(base), int(st.size() - base), es.eps);
    st.resize(base + std::uint32_t(count));
    return std::uint32_t(count);
}

std::uint32_t intersection_spans(RayState& es, const Node& n, double a, double b) {
    es.scratch->counters.intersection_ops++;
    SpanStack& st = es.scratch->stack;
    const std::uint32_t base = st.size();
    std::uint32_t count = 0;
    for (std::uint32_t k = 0; k < n.count; ++k) {
        const std::uint32_t child = es.impl->scene.children[n.first + k];
        if (k == 0) {
            count = es.spans(child, a, b, Need::All);
        } else {
            // Later operands matter only where the running result is inside.
            const double wa = std::max(a, st.at(base)->t0);
            const double wb = std::min(b, st.at(base + count - 1)->t1);
            const std::uint32_t m = es.spans(child, wa, wb, Need::All);
            const std::uint32_t rbase = base + count + m;
            st.resize(rbase + count + m);
            const int r =
                span_intersection(st.at(base), int(count), st.at(base + count), int(m), st.at(rbase), es.eps);
            std::copy(st.at(rbase), st.at(rbase) + r, st.at(base));
            count = std::uint32_t(r);
        }
        st.resize(base + count);
        if (count == 0) return 0;  // an empty operand empties the intersection
    }
    return count;
}

std::uint32_t difference_spans(RayState& es, std::uint32_t node, const Node& n, double a, double b, Need need) {
    es.scratch->counters.difference_ops++;
    SpanStack& st = es.scratch->stack;
    const std::uint32_t base = st.size();
    const std::uint32_t count = es.spans(es.impl->scene.children[n.first], a, b, Need::All);
    if (count == 0 || n.count == 1) return count;  // empty minuend: nothing to subtract from
    const std::uint32_t sbase = base + count;
    int r = 0;
    if (need == Need::All) {
        // Subtrahends matter only where the minuend is inside.
        collect_children(es, node, n, 1, std::max(a, st.at(base)->t0), std::min(b, st.at(sbase - 1)->t1));
        const std::uint32_t rbase = es.subtract_gathered(base, count, sbase, r);
        std::copy(st.at(rbase), st.at(rbase) + r, st.at(base));
        st.resize(base + std::uint32_t(r));
        return std::uint32_t(r);
    }
    // First/Any: one minuend span at a time, stopping at the first piece that
    // answers the question; only that piece is returned.
    const std::int32_t ai = es.impl->accel_of_node[node];
    const bool few = ai < 0 || !es.impl->node_accels[std::size_t(ai)]->bvh;
    for (std::uint32_t i = 0; i < count; ++i) {
        if (few) {
            const FastPath found = es.first_piece_if_clear(n, base, sbase, i, a, b, need);
            if (found == FastPath::Found) return 1;
            if (found == FastPath::Past) break;
            if (found == FastPath::None) continue;
        }
        if (need == Need::First && !few && st.at(base + i)->t0 > a) {
            // Many subtrahends: walk from the minuend's entry with point
            // queries ("which subtrahends cover c?") instead of gathering all
            // of them along the chord, so the cost does not grow with the
            // number of holes the chord passes.
            const std::uint32_t found = es.first_entry_by_points(*es.impl->node_accels[std::size_t(ai)], base, i, b);
            if (found == 1) return 1;
            if (found == 2) break;  // beyond the window: nothing to find
            continue;
        }
        if (need == Need::Any && !few && !es.impl->node_accels[std::size_t(ai)]->grid.empty()) {
            // Many subtrahends and a grid: only those near probes of the span.
            const FastPath found = es.any_by_points(*es.impl->node_accels[std::size_t(ai)], base, sbase, i, a, b);
            if (found == FastPath::Found) return 1;
            if (found == FastPath::None) continue;
        }
        const double wa = std::max(a, st.at(base + i)->t0), wb = std::min(b, st.at(base + i)->t1);
        st.resize(sbase);
        collect_children(es, node, n, 1, wa, wb);
        const std::uint32_t rbase = es.subtract_gathered(base + i, 1, sbase, r);
        for (int k = 0; k < r; ++k) {
            const Span piece = *st.at(rbase + std::uint32_t(k));
            const bool answers = need == Need::First
                                     ? piece.t0 > a && piece.t0 <= b
                                     : std::min(piece.t1, b) - std::max(piece.t0, a) > es.eps;
            if (answers) {
                *st.at(base) = piece;
                st.resize(base + 1);
                return 1;
            }
        }
    }
    st.resize(base);
    return 0;
}

}  // namespace

std::uint32_t RayState::spans(std::uint32_t node, double a, double b, Need need) {
    const Node& n = impl->scene.nodes[node];
    // Also under Embree's callbacks: a BVH leaf may hold several items and a
    // root that is a leaf is entered without any box test, so a one-unit
    // scene would otherwise test its primitives for every ray of the image.
    if (!box_hit(*this, impl->padded[node], a, b)) return 0;
    // Two analytic leaves in one step (leaf_pair_spans); a difference asked
    // for its first entry or any span keeps its fast path
    // (difference_fast_path.cpp).
    switch (n.op) {
        case Op::Leaf: return leaf_spans(*this, n, a, b);
        case Op::Union: return impl->leaf_pair[node] ? leaf_pair_spans(*this, n, a, b) : union_spans(*this, node, n, a, b);
        case Op::Intersection:
            return impl->leaf_pair[node] ? leaf_pair_spans(*this, n, a, b) : intersection_spans(*this, n, a, b);
        case Op::Difference:
            if (need != Need::All && impl->leaf_minus[node]) return leaf_minus_spans(n, a, b, need);
            return impl->leaf_pair[node] && need == Need::All ? leaf_pair_spans(*this, n, a, b)
                                                               : difference_spans(*this, node, n, a, b, need);
    }
    return 0;
}

void RayState::collect_candidates(const Accel& accel, const std::uint32_t* cand, int n, double a, double b) {
    for (std::uint32_t node : accel.always) spans(node, a, b, Need::All);
    for (int k = 0; k < n; ++k) spans(cand[k], a, b, Need::All);
}

void RayState::collect(const Accel& accel, double a, double b) {
    std::uint32_t cand[kGridCandidates];
    if (const int n = grid_candidates(accel, a, b, cand); n >= 0) return collect_candidates(accel, cand, n, a, b);
    for (std::uint32_t node : accel.always) spans(node, a, b, Need::All);
    if (!accel.bvh) {
        for (std::uint32_t node : accel.items) spans(node, a, b, Need::All);
        return;
    }
    CollectContext ctx;
    rtcInitIntersectContext(&ctx.rtc);
    ctx.state = this;
    ctx.accel = &accel;
    ctx.a = a;
    ctx.b = b;
    float_ray_now(*this);
    RTCRayHit rh = make_rayhit(*this, a, b);
    accel.ready();
    rtcIntersect1(accel.bvh, &ctx.rtc, &rh);
}

}  // namespace kerf::render

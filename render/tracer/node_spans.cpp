// Windowed spans of the CSG tree (README.md, "Inside a unit"):
// spans(node, a, b) pushes the node's spans that overlap [a, b] onto the
// thread's span stack, correct on that window. Box culling, primitive leaves
// and the union / intersection / difference combinations live in this one
// file because they call each other recursively on the hot path and must
// stay inlinable into each other. Mesh leaves are in mesh_spans.cpp, the
// point-query first entry of big differences in difference_first_entry.cpp,
// the clearance fast path of small ones in difference_fast_path.cpp.
#include <algorithm>

#include "render/primitives/primitives.hpp"
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

// `box` is already padded by the degenerate rule's reach (Impl::padded).
bool box_hit(const RayState& es, const csg::Aabb& box, double a, double b) {
    return slab_hit(box, es.o, es.invd, a - es.eps, b + es.eps);
}

std::uint32_t leaf_spans(RayState& es, const Node& n, double a, double b) {
    const csg::Leaf& leaf = es.impl->scene.leaves[n.first];
    if (leaf.kind == csg::PrimKind::Mesh) return es.mesh_spans(n.first, a, b);
    if (leaf.kind == csg::PrimKind::Prism || leaf.kind == csg::PrimKind::Lathe) return prism_spans(es, n.first, a, b);
    // A leaf only moved (most are: translate, or none) skips the matrix:
    // 1·x + 0·y + 0·z is x, so the numbers are the same.
    const bool shift = es.impl->leaf_shift_only[n.first];
    const glm::dvec3 lo = shift ? es.o + leaf.object_from_world.offset : leaf.object_from_world.point(es.o);
    const glm::dvec3 ld = shift ? es.d : leaf.object_from_world.vector(es.d);
    csg::Span<double> spans[csg::kMaxSpans];
    // Span ends outside the window (with room for the degenerate rule) may
    // be reported inexactly: nothing reads them (see spans' contract).
    const double wa = a - 4 * es.eps, wb = b + 4 * es.eps;
    int count;
    if (es.impl->use_float) {
        csg::Span<float> fs[csg::kMaxSpans];
        count = csg::intersect_leaf<float>(leaf, glm::vec3(lo), glm::vec3(ld), fs, float(wa), float(wb));
        for (int i = 0; i < count; ++i) spans[i] = {double(fs[i].t0), double(fs[i].t1), fs[i].part0, fs[i].part1};
    } else {
        count = csg::intersect_leaf<double>(leaf, lo, ld, spans, wa, wb);
    }
    es.scratch->counters.interval_tests++;
    es.scratch->counters.spans_found += std::uint64_t(count);
    const std::uint32_t leaf_id = n.first;
    std::uint32_t pushed = 0;
    for (int i = 0; i < count; ++i) {
        if (spans[i].t1 < a || spans[i].t0 > b) continue;
        Span s;
        s.t0 = spans[i].t0;
        s.t1 = spans[i].t1;
        s.e0 = SpanEnd{leaf_id, leaf_id, spans[i].part0, 0, 0, 0};
        s.e1 = SpanEnd{leaf_id, leaf_id, spans[i].part1, 0, 0, 0};
        s.inner = leaf_id;
        es.scratch->stack.push(s);
        ++pushed;
    }
    return pushed;
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
    switch (n.op) {
        case Op::Leaf: return leaf_spans(*this, n, a, b);
        case Op::Union: return union_spans(*this, node, n, a, b);
        case Op::Intersection: return intersection_spans(*this, n, a, b);
        case Op::Difference: return difference_spans(*this, node, n, a, b, need);
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
    RTCRayHit rh = make_rayhit(*this, a, b);
    rtcIntersect1(accel.bvh, &ctx.rtc, &rh);
}

}  // namespace kerf::render

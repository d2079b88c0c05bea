// The spans of an analytic leaf (sphere, box, cylinder, torus, plane,
// paraboloid, hyperboloid: at most csg::kMaxSpans, no per-thread buffers)
// along the state's ray, shared by the span stack's leaves (node_spans.cpp)
// and the one-step evaluations that keep them in locals (leaf pairs there,
// a leaf minus a few leaves in leaf_minus.cpp). Inline: it is the inner
// loop of both.
#pragma once
#include <cstdint>

#include "render/primitives/primitives.hpp"
#include "render/tracer/ray_state.hpp"

namespace kerf::render {

// Room for N spans in locals, left uninitialised: SpanEnd's member
// initialisers would clear every local array on every call, and most of
// them are never read.
template <int N>
struct SpanBuffer {
    union {
        Span at[N];
    };
    SpanBuffer() {}
};

// Whether a node's padded box (Impl::padded: grown by the degenerate rule's
// reach) meets the ray on [a, b] widened by eps.
inline bool box_hit(const RayState& es, const csg::Aabb& box, double a, double b) {
    return slab_hit(box, es.o, es.invd, a - es.eps, b + es.eps);
}

// The analytic leaf's spans that overlap [a, b], each handed to put;
// returns their count. Its box test is the caller's. `ahead`: the leaf's
// spans along the ray if solved already (CsgTracer::solve_ahead), taken
// when they are this leaf's along this ray; only leaf_minus_spans' minuend
// passes them (the one leaf solve_ahead solves), so no other call pays
// for the check.
template <typename Put>
[[gnu::always_inline]] inline int analytic_spans(RayState& es, std::uint32_t leaf_id, double a, double b, Put put,
                                                 const AheadSpans* ahead = nullptr) {
    const csg::Leaf& leaf = es.impl->scene.leaves[leaf_id];
    const glm::dvec3 lo = es.impl->leaf_point(leaf_id, es.o), ld = es.impl->leaf_vector(leaf_id, es.d);
    csg::Span<double> spans[csg::kMaxSpans];
    // Span ends outside the window (with room for the degenerate rule) may
    // be reported inexactly: nothing reads them (see spans' contract).
    const double wa = a - 4 * es.eps, wb = b + 4 * es.eps;
    int count;
    if (ahead && ahead->leaf == leaf_id && ahead->o == es.o && ahead->d == es.d) {
        count = ahead->count;
        for (int i = 0; i < count; ++i) spans[i] = ahead->spans[i];
    } else if (es.impl->use_float) {
        csg::Span<float> fs[csg::kMaxSpans];
        count = csg::intersect_leaf<float>(leaf, glm::vec3(lo), glm::vec3(ld), fs, float(wa), float(wb));
        for (int i = 0; i < count; ++i) spans[i] = {double(fs[i].t0), double(fs[i].t1), fs[i].part0, fs[i].part1};
    } else {
        count = csg::intersect_leaf<double>(leaf, lo, ld, spans, wa, wb);
    }
    es.scratch->counters.interval_tests++;
    es.scratch->counters.spans_found += std::uint64_t(count);
    int kept = 0;
    for (int i = 0; i < count; ++i) {
        if (spans[i].t1 < a || spans[i].t0 > b) continue;
        Span s;
        s.t0 = spans[i].t0;
        s.t1 = spans[i].t1;
        s.e0 = SpanEnd{leaf_id, leaf_id, spans[i].part0, 0, 0, 0};
        s.e1 = SpanEnd{leaf_id, leaf_id, spans[i].part1, 0, 0, 0};
        s.inner = leaf_id;
        put(s);
        ++kept;
    }
    return kept;
}

// The spans of the analytic leaf node `node` on [a, b] written to out, its
// box test first: what RayState::spans pushes for it.
[[gnu::always_inline]] inline int analytic_node_spans(RayState& es, std::uint32_t node, double a, double b, Span* out,
                                                      const AheadSpans* ahead = nullptr) {
    if (!box_hit(es, es.impl->padded[node], a, b)) return 0;
    return analytic_spans(es, es.impl->scene.nodes[node].first, a, b, [&out](const Span& s) { *out++ = s; }, ahead);
}

}  // namespace kerf::render

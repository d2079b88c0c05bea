// Crowds of bare spheres (Impl::bare_spheres: every unit of the root a
// sphere leaf, double path; the spheres_* lattices): a camera or shadow
// ray in a ray cone (ray_cones.hpp) is served by bare_spheres.cpp without
// the general query's set-up (no float Embree ray, no TopContext), and
// each unit the cone lists is its ball test, its padded box and its
// leaf's sphere test, in locals. The general visit (first_hit.cpp try_unit_entry,
// shadow_rays.cpp unit_blocks) reaches the same tests through spans(): the
// node switch, the leaf-kind dispatch, a push onto the span stack and the
// walk of what was pushed, about half of a camera ray's work in such a
// crowd. The numbers are the same calls on the same operands (the box
// test of analytic_spans.hpp's box_hit, the leaf's object-space ray of
// Impl::leaf_point/leaf_vector, csg::solve_sphere<double>), the
// window filters those of analytic_spans and the callers: the same bits.
#pragma once
#include <algorithm>
#include <cstdint>

#include "render/primitives/kinds.hpp"
#include "render/primitives/sphere.hpp"
#include "render/tracer/analytic_spans.hpp"

namespace kerf::render {

// The sphere leaf `node`'s span overlapping [a, b], as spans(node, a, b, ·)
// pushes it (the leaf's box test first); false when it pushes none. The
// degenerate rule is the caller's (RayState::enter_unit).
[[gnu::always_inline]] inline bool bare_sphere_span(RayState& st, std::uint32_t node, double a, double b, Span& out) {
    const CsgTracer::Impl& impl = *st.impl;
    if (!box_hit(st, impl.padded[node], a, b)) return false;
    const std::uint32_t leaf = impl.scene.nodes[node].first;
    csg::Span<double> sp[csg::kMaxSpans];
    const int count =
        csg::solve_sphere<double>(impl.scene.leaves[leaf].p, impl.leaf_point(leaf, st.o), impl.leaf_vector(leaf, st.d), sp);
    st.scratch->counters.interval_tests++;
    st.scratch->counters.spans_found += std::uint64_t(count);
    if (count == 0 || sp[0].t1 < a || sp[0].t0 > b) return false;
    out.t0 = sp[0].t0;
    out.t1 = sp[0].t1;
    out.e0 = SpanEnd{leaf, leaf, sp[0].part0, 0, 0, 0};
    out.e1 = SpanEnd{leaf, leaf, sp[0].part1, 0, 0, 0};
    out.inner = leaf;
    return true;
}

// Whether unit `item` blocks the shadow segment (a, b), as unit_blocks
// decides for a unit that is no Departure's hollow: its span's part inside
// the window longer than the degenerate rule.
[[gnu::always_inline]] inline bool bare_sphere_blocks(RayState& st, std::uint32_t item, std::uint32_t node, double a,
                                                      double b) {
    if (unit_ball_misses(st, item, a, b)) return false;
    st.enter_unit(node);
    Span sp;
    return bare_sphere_span(st, node, a, b, sp) && std::min(sp.t1, b) - std::max(sp.t0, a) > st.eps;
}

// The nearest first entry among the units offered, in any order (a cone's
// list, the grid's cells): ties go by unit index, as take_entry's
// (first_hit.cpp). `best` starts at the window's end and only shrinks, so
// the cone loop and the grid walk stop on it.
struct NearestBare {
    double best;
    std::uint32_t best_unit = 0;
    bool found = false;
    std::uint32_t leaf = 0;  // the entry's surface: SpanEnd{leaf, leaf, part}
    std::uint8_t part = 0;
    [[gnu::always_inline]] void offer(RayState& st, std::uint32_t item, std::uint32_t node, double a) {
        if (!unit_ball_misses(st, item, a, best)) take(st, item, node, a);
    }
    // offer() past the unit's ball test (which the caller made).
    [[gnu::always_inline]] void take(RayState& st, std::uint32_t item, std::uint32_t node, double a) {
        st.enter_unit(node);
        Span entry;
        if (!(bare_sphere_span(st, node, a, best, entry) && entry.t0 > a)) return;
        if (!(entry.t0 < best || (entry.t0 == best && found && item < best_unit))) return;
        best = entry.t0;
        best_unit = item;
        leaf = entry.e0.leaf;
        part = entry.e0.part;
        found = true;
    }
    // Field by field: a SpanEnd put together in registers and copied whole
    // stalled on the store forwarding of its pieces (~10 % of the grid
    // walk's samples).
    int answer(TraceHit& hit) const {
        if (!found) return 0;
        hit.t = best;
        hit.surface.leaf = leaf;
        hit.surface.mat_leaf = leaf;
        hit.surface.part = part;
        hit.surface.flip = 0;
        hit.surface.cut = 0;
        hit.surface.prim = 0;
        return 1;
    }
};

// bare_spheres.cpp: CsgTracer::intersect and occluded for a ray of a cone
// in a bare-sphere crowd (`skip`: the Departure's unit, or kNone); -1 when
// the ray has no cone (the caller asks the general path), else the answer.
int bare_first_hit(const CsgTracer::Impl& impl, const TraceRay& ray, TraceHit& hit, TraceScratch& scratch);
int bare_occluded(const CsgTracer::Impl& impl, const TraceRay& ray, TraceScratch& scratch, std::uint32_t skip);
// sphere_grid.cpp: the same for a crowd with a SphereGrid (past the cones'
// units), its ray's state made; -1 when the ray rounds beyond the grid's
// margin (SphereGrid::fits).
int grid_first_hit(RayState& st, const TraceRay& ray, TraceHit& hit);
// grid_occluded names the blocking unit in `by`.
int grid_occluded(RayState& st, const TraceRay& ray, std::uint32_t skip, std::uint32_t& by);

}  // namespace kerf::render

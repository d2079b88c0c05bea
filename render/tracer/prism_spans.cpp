// Prism and lathe leaves in the tracer: intersect_prism / intersect_lathe
// in object space with
// per-thread buffers sized for the largest section seen (they only grow: no
// allocation per ray once warm), spans shorter than the degenerate rule's
// eps dropped (a zero-area section's edges cross in pairs a rounding apart),
// then pushed like any leaf's, the edge riding in SpanEnd::prim. A section
// of many edges gets a grid (primitives/prism_grid.hpp), built with the tracer.
#include "render/tracer/prism_spans.hpp"

#include <vector>

#include "render/primitives/lathe.hpp"
#include "render/primitives/prism.hpp"
#include "render/tracer/ray_state.hpp"

namespace kerf::render {

namespace {

template <typename T>
struct PrismBuffers {
    std::vector<csg::PrismSpan<T>> spans;
    std::vector<csg::PrismCrossing<T>> crossings;
    void fit(std::size_t crossing_room, std::size_t span_room) {
        if (crossings.size() < crossing_room) crossings.resize(crossing_room);
        if (spans.size() < span_room) spans.resize(span_room);
    }
};

template <typename T>
int prism_in(const csg::Polygon2& poly, const csg::PrismGrid* grid, const csg::Leaf& leaf, const glm::dvec3& o,
             const glm::dvec3& d, double wa, double wb, std::vector<csg::PrismSpan<double>>& out) {
    thread_local PrismBuffers<T> buf;
    const std::size_t edges = poly.edges.size();
    int n;
    if (leaf.kind == csg::PrimKind::Lathe) {
        buf.fit(csg::lathe_crossing_room(edges), csg::lathe_span_room(edges));
        n = csg::intersect_lathe<T>(poly, glm::vec<3, T>(o), glm::vec<3, T>(d), buf.spans.data(), buf.crossings.data());
    } else {
        buf.fit(edges, csg::prism_span_room(edges, leaf.p));
        n = csg::intersect_prism<T>(poly, leaf.p, glm::vec<3, T>(o), glm::vec<3, T>(d), buf.spans.data(),
                                    buf.crossings.data(), T(wa), T(wb), grid);
    }
    if (out.size() < buf.spans.size()) out.resize(buf.spans.size());
    for (int i = 0; i < n; ++i) {
        const csg::PrismSpan<T>& s = buf.spans[std::size_t(i)];
        out[std::size_t(i)] = {{double(s.s.t0), double(s.s.t1), s.s.part0, s.s.part1}, s.edge0, s.edge1};
    }
    return n;
}

}  // namespace

// One grid per section that a straight or tapered prism leaf extrudes,
// however many leaves share it (lathes and swept prisms test every edge).
void CsgTracer::Impl::build_prism_grids() {
    if (scene.polygons.empty()) return;  // (no pass over 10^5 leaves for nothing)
    std::vector<char> wanted(scene.polygons.size(), 0);
    for (const csg::Leaf& leaf : scene.leaves)
        if (leaf.kind == csg::PrimKind::Prism && leaf.polygon < wanted.size() && !csg::is_swept(leaf.p))
            wanted[leaf.polygon] = 1;
    prism_grids.resize(scene.polygons.size());
    for (std::size_t i = 0; i < wanted.size(); ++i)
        if (wanted[i]) prism_grids[i] = csg::build_prism_grid(scene.polygons[i]);
}

std::uint32_t prism_spans(RayState& es, std::uint32_t leaf_id, double a, double b) {
    const csg::Leaf& leaf = es.impl->scene.leaves[leaf_id];
    if (leaf.polygon >= es.impl->scene.polygons.size()) return 0;
    const csg::Polygon2& poly = es.impl->scene.polygons[leaf.polygon];
    const glm::dvec3 lo = leaf.object_from_world.point(es.o);
    const glm::dvec3 ld = leaf.object_from_world.vector(es.d);
    const double wa = a - 4 * es.eps, wb = b + 4 * es.eps;
    const csg::PrismGrid* grid = leaf.polygon < es.impl->prism_grids.size() ? &es.impl->prism_grids[leaf.polygon] : nullptr;
    thread_local std::vector<csg::PrismSpan<double>> spans;
    const int count = es.impl->use_float ? prism_in<float>(poly, grid, leaf, lo, ld, wa, wb, spans)
                                         : prism_in<double>(poly, grid, leaf, lo, ld, wa, wb, spans);
    es.scratch->counters.interval_tests++;
    std::uint32_t pushed = 0;
    for (int i = 0; i < count; ++i) {
        const csg::PrismSpan<double>& p = spans[std::size_t(i)];
        if (p.s.t1 - p.s.t0 <= es.eps || p.s.t1 < a || p.s.t0 > b) continue;
        Span s;
        s.t0 = p.s.t0;
        s.t1 = p.s.t1;
        s.e0 = SpanEnd{leaf_id, leaf_id, p.s.part0, 0, 0, p.edge0};
        s.e1 = SpanEnd{leaf_id, leaf_id, p.s.part1, 0, 0, p.edge1};
        s.inner = leaf_id;
        es.scratch->stack.push(s);
        ++pushed;
    }
    es.scratch->counters.spans_found += pushed;
    return pushed;
}

}  // namespace kerf::render

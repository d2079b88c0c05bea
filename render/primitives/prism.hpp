// The prism leaf (PrimKind::Prism): a polygon set filled by the even-odd
// rule (csg::Polygon2) times the slab z0 < z < z1, its section scaled by
// 1 + p[2]·(z − z0)/(z1 − z0) (p[2] = 0: straight; linear_extrude's scale − 1), in y by that plus
// p[3], and turned by −p[4]·(z − z0)/(z1 − z0) radians first (a swept prism:
// swept_prism.cpp). Unlike the other
// primitives it has any number of spans along a line (a concave section),
// so it has its own entry point with caller-provided buffers instead of
// intersect_leaf's two spans. Its side part is one polygon edge, named by
// the span end's edge index.
#pragma once
#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/primitives/primitives.hpp"

namespace kerf::csg {

// Side parts: the outward normal is +perp(edge) = (ey, -ex, 0) or its negation
// (even-odd filling gives an edge no orientation of its own).
constexpr std::uint8_t kPartEdge = 0;
constexpr std::uint8_t kPartEdgeFlipped = 3;

template <typename T>
struct PrismSpan {
    Span<T> s;
    std::uint32_t edge0, edge1;  // side parts: the edge hit at each end
};

template <typename T>
struct PrismCrossing {
    T s;                // along the ray, relative to its shift (prism.cpp)
    std::uint32_t edge;
    bool plus;          // cross(d_xy, edge) > 0
};

// One end of a span (prism and lathe leaves): its position and part.
template <typename T>
struct PrismEnd {
    T s;
    std::uint8_t part;
    std::uint32_t edge;
};

// The side part whose outward normal faces against the ray at an entry
// (along it at an exit): +perp(e) faces along d exactly when `plus`.
inline std::uint8_t edge_part(bool plus, bool entering) {
    return plus != entering ? kPartEdge : kPartEdgeFlipped;
}

// Appends the span [tc + a.s, tc + b.s] (spans come in increasing order) if
// it keeps a positive length; a gap that rounds to nothing merges it with
// the previous span (degenerate rule, docs/accuracy.md).
template <typename T>
void emit_prism_span(PrismSpan<T>* out, int& n, T tc, const PrismEnd<T>& a, const PrismEnd<T>& b) {
    const T t0 = tc + a.s, t1 = tc + b.s;
    if (!(t0 < t1)) return;
    if (n > 0 && !(out[n - 1].s.t1 < t0)) {
        out[n - 1].s.t1 = t1;
        out[n - 1].s.part1 = b.part;
        out[n - 1].edge1 = b.edge;
        return;
    }
    out[n++] = PrismSpan<T>{Span<T>{t0, t1, a.part, b.part}, a.edge, b.edge};
}

// A section map that is not a uniform positive scale: a top scale 0, a
// scale differing in x and y, or a twist (swept_prism.cpp).
inline bool is_swept(const double* p) { return p[2] == -1 || p[3] != 0 || p[4] != 0; }

// Crossings a swept prism's sides may have along a ray: edges × (2 + 2 per half turn).
std::size_t swept_crossing_room(std::size_t edges, const double* p);

// Room intersect_prism needs: spans and crossings for a section of n edges.
inline std::size_t prism_span_room(std::size_t edges) { return edges / 2 + 2; }
inline std::size_t prism_span_room(std::size_t edges, const double* p) {
    return is_swept(p) ? swept_crossing_room(edges, p) / 2 + 2 : prism_span_room(edges);
}

// The swept prism's spans (at most `room`), caps exact, sides to rounding
// (closed-form roots without a twist, bracketed and refined ones with it);
// crossings in its own per-thread scratch.
template <typename T>
int intersect_swept_prism(const Polygon2& poly, const double* p, const glm::vec<3, T>& o, const glm::vec<3, T>& d,
                          PrismSpan<T>* out, int room);
glm::dvec3 normal_swept_prism(const Polygon2& poly, const double* p, std::uint8_t part, std::uint32_t edge,
                              const glm::dvec3& x);

struct PrismGrid;

// Sorted, disjoint spans of positive length of o + t·d inside the prism,
// each end exact (caps, edges); the window [wa, wb] only limits which
// crossings are sorted: spans not overlapping it may be left out. `out`
// holds prism_span_room(edges, p) spans, `scratch` edges crossings.
// `grid` (prism_grid.hpp, built from `poly`), when given and not empty,
// picks the edges to test: the same spans, bit for bit, from fewer tests
// (straight and tapered prisms; a swept prism tests every edge).
template <typename T>
int intersect_prism(const Polygon2& poly, const double* p, const glm::vec<3, T>& o, const glm::vec<3, T>& d,
                    PrismSpan<T>* out, PrismCrossing<T>* scratch, T wa = -std::numeric_limits<T>::infinity(),
                    T wb = std::numeric_limits<T>::infinity(), const PrismGrid* grid = nullptr);

// Outward object-space normal of surface `part` (edge: `edge`) of the prism
// with parameters p at object point x (a swept prism's sides curve).
glm::dvec3 normal_prism(const Polygon2& poly, const double* p, std::uint8_t part, std::uint32_t edge,
                        const glm::dvec3& x = glm::dvec3(0));

}  // namespace kerf::csg

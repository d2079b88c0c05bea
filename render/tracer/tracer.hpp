// Ray–CSG queries over a csg::Scene on top of Embree 3 (design: README.md).
// Built once per scene; const and thread-safe afterwards. Each thread passes
// its own TraceScratch (span stack and counters), so tracing never locks or
// allocates per ray.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"
#include "render/primitives/primitives.hpp"
#include "render/tracer/ray_cones.hpp"
#include "render/tracer/span_list.hpp"

namespace kerf::render {

struct TraceCounters {
    std::uint64_t union_ops = 0, difference_ops = 0, intersection_ops = 0;
    std::uint64_t interval_tests = 0;  // intersect_leaf calls
    std::uint64_t spans_found = 0;     // primitive intervals those calls returned
    std::uint64_t grid_cells = 0;      // cells a big bare crowd's rays walked (sphere_grid.hpp)
    std::uint64_t listed_shadows = 0;  // shadow rays answered by the units toward their light (toward_light.hpp)
};

// A leaf's spans along one ray, solved ahead of the query that needs them
// (CsgTracer::solve_ahead).
struct AheadSpans {
    std::uint32_t leaf;
    int count;
    glm::dvec3 o, d;
    csg::Span<double> spans[csg::kMaxSpans];
};

struct TraceScratch {
    SpanStack stack;
    TraceCounters counters;
    RayCones cones;  // this thread's ray cones (ray_cones.hpp)
    // Set by the caller round one query: that leaf's spans along the
    // query's ray, which the query takes instead of solving it again.
    const AheadSpans* ahead = nullptr;
    // A bare-sphere crowd's shadow rays (bare_spheres.cpp): the unit that
    // blocked this thread's last blocked one, tried first by the next (a
    // shadow's neighbouring points are blocked by the same sphere), and
    // the tracer it belongs to (CsgTracer::Impl::id; 0: none).
    std::uint64_t blocker_owner = 0;
    std::uint32_t blocker = 0;
};

// d need not be unit length; t is measured in units of d.
struct TraceRay {
    glm::dvec3 o, d;
    double tnear = 0, tfar = 0;
};

struct TraceHit {
    double t = 0;
    SpanEnd surface;  // the root solid's entry surface
};

// Where a shadow ray starts: just off a hit surface, along `outward` (the
// surface's outward unit normal there, as CsgTracer::normal gives it). When
// that surface is a convex leaf holding its whole unit (CsgTracer::departure),
// a ray leaving it outwards can never meet that unit again, so occluded()
// skips the unit: one primitive test fewer per shadow ray of a lit point.
// A subtrahend's face instead (a hole's wall): the ray starts in that
// convex leaf, inside which its difference, and so the unit it holds, has
// nothing; occluded() asks that unit only from where the ray leaves the
// leaf (shadow_rays.cpp, "Departure into a subtrahend").
struct Departure {
    std::uint32_t unit = csg::kNone;  // the unit to skip, or kNone
    glm::dvec3 outward{0.0};
    std::uint32_t hollow = csg::kNone;  // the root node of the unit the leaf cuts, or kNone
    std::uint32_t into = csg::kNone;    // the subtrahend leaf's node
};

class CsgTracer {
public:
    CsgTracer(const csg::Scene& scene, bool use_float);
    ~CsgTracer();
    CsgTracer(const CsgTracer&) = delete;
    CsgTracer& operator=(const CsgTracer&) = delete;

    // First entry of the root solid with tnear < t < tfar.
    bool intersect(const TraceRay& ray, TraceHit& hit, TraceScratch& scratch) const;
    // For the n camera rays of a run of pixels, before any is traced: the
    // spans of the leaf each one's query starts with (the sphere minuend of
    // a one-unit scene's leaf minus leaves: a grooved sphere), in out[0, n).
    // Solved in one loop, the rays' chains of a division, a square root and
    // two divisions overlap instead of each stalling its own query. False
    // (nothing written) when the scene has no such leaf. Hand out[i] to ray
    // i's query in TraceScratch::ahead: it takes the same bits it would
    // have solved.
    bool solve_ahead(const TraceRay* rays, int n, AheadSpans* out) const;
    // Whether the root solid has a span of positive length inside (tnear, tfar).
    // `from`: the ray leaves that surface (shadow_rays.cpp, "Departure").
    bool occluded(const TraceRay& ray, TraceScratch& scratch, const Departure* from = nullptr) const;
    // Every span of the root solid on (tnear, tfar), sorted and disjoint,
    // clipped to the window (`kerf measure`: chord lengths, inside_spans.cpp).
    void inside_spans(const TraceRay& ray, TraceScratch& scratch, std::vector<Span>& out) const;

    // True if every ray whose origin and direction are convex combinations
    // of these four corner rays (in order round a quad) misses the solid:
    // a whole image tile can then be filled without tracing (tile_cull.cpp).
    bool misses_all(const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4]) const;
    // Unit by unit (tile_cull.cpp; the scene's units are culled so when
    // cull_unit_count() > 0): the units some ray of the quad may meet, of
    // among[0, n) (every one when among is null), written to `near` (room
    // for cull_unit_count()), their count returned; 0: every ray misses the
    // solid, as misses_all says. -1: units are not culled one by one. The
    // units a quad's list leaves out are missed by the rays of any quad
    // inside it, so an image block asks only its tile's list.
    int near_units(const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4], const std::uint32_t* among, int n,
                   std::uint32_t* near) const;
    std::size_t cull_unit_count() const;
    // World unit normal of the final solid at a hit point.
    glm::dvec3 normal(const TraceHit& hit, const glm::dvec3& world_point) const;

    // The Departure of a ray leaving `hit`'s surface along its normal
    // `outward` (unit kNone when the surface is not a convex leaf holding
    // its unit, or is a subtrahend's flipped face; hollow set for a convex
    // subtrahend's face).
    Departure departure(const TraceHit& hit, const glm::dvec3& outward) const;

    // How far along its normal a ray leaving the surface of `hit` at `p`
    // starts (shadows, reflections): above the local degenerate rule
    // (tolerances.cpp), world units.
    double surface_offset(const TraceHit& hit, const glm::dvec3& p) const;

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

// True if every ray of the four corner rays' hull (as misses_all) misses
// `box`: an empty box always, one with an infinite coordinate never.
bool tile_misses_box(const csg::Aabb& box, const glm::dvec3 (&o)[4], const glm::dvec3 (&d)[4]);

}  // namespace kerf::render

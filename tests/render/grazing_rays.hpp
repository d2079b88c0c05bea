// Rays that graze spheres, for the tracer's oracle tests of crowds (ray
// cones, bare spheres): a ball to aim at, a direction at it that meets its
// surface within a band or runs tangent to it, a camera ray's check, and a
// shadow ray with its first entry checked by point membership.
#pragma once
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "render/tracer/tracer.hpp"
#include "tests/render/random_csg.hpp"

namespace kerf::test {

struct Ball {
    glm::dvec3 c;
    double r;
};

// A direction from p towards ball b: at a point within ±band of its surface,
// or (every other one) tangent to it, tilted in or out by up to `band` / 1000.
inline glm::dvec3 aim(RandomCsg& g, const glm::dvec3& p, const Ball& b, double band, bool tangent) {
    const glm::dvec3 u = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
    if (!tangent) return glm::normalize(b.c + g.uni(1 - band, 1 + band) * b.r * u - p);
    const glm::dvec3 w = b.c - p;
    const double dw = glm::length(w), beta = std::asin(b.r / dw) * (1 + 1e-3 * g.uni(-band, band));
    const glm::dvec3 e = glm::normalize(u - glm::dot(u, w) / (dw * dw) * w);
    return std::cos(beta) * (w / dw) + std::sin(beta) * e;
}

// A camera ray traced on a fresh thread and on `primed` (whose cones
// earlier rays built): the same entry and the same work, the entry checked
// by point membership (on (0, t_end), step h). True if it hits (the hit in
// `out`, if given).
inline bool camera_ray_agrees(const csg::Scene& s, const render::CsgTracer& tracer, const render::TraceRay& ray,
                              render::TraceScratch& fresh, render::TraceScratch& primed, double t_end, double h,
                              render::TraceHit* out = nullptr) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    render::TraceHit hit, hit2;
    const bool found = tracer.intersect(ray, hit, fresh);
    const std::uint64_t tests = primed.counters.interval_tests;
    const bool found2 = tracer.intersect(ray, hit2, primed);
    CHECK(found == found2);
    CHECK((found ? hit.t : kInf) == (found2 ? hit2.t : kInf));
    CHECK(fresh.counters.interval_tests == primed.counters.interval_tests - tests);
    const double t = found ? hit.t : kInf;
    INFO("camera ray entry " << t);
    CHECK(is_first_entry(s, ray.o, ray.d, t, t_end, h));
    if (out) *out = hit;
    return found;
}

// A shadow ray as shading makes it (unit dir, tfar the distance) from a
// point size·(lo..hi) from the light, outside the solid, aimed near ball b (see
// aim), with the tracer's first entry along it (te) checked by point
// membership (h: the oracle's step). False when the point is inside.
struct ShadowRay {
    glm::dvec3 o, dir;
    double dist, te;
};
inline bool shadow_ray(RandomCsg& g, const csg::Scene& s, const render::CsgTracer& tracer, const glm::dvec3& light,
                       const Ball& b, double band, bool tangent, double size, double lo, double hi, double h,
                       render::TraceScratch& scratch, ShadowRay& r) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const glm::dvec3 ds = -aim(g, light, b, band, tangent);
    r.o = light - size * g.uni(lo, hi) * ds;
    if (csg_contains(s, r.o)) return false;
    r.dist = glm::length(light - r.o);
    r.dir = (light - r.o) / r.dist;
    render::TraceHit entry;
    r.te = tracer.intersect(render::TraceRay{r.o, r.dir, 0, kInf}, entry, scratch) ? entry.t : kInf;
    CHECK(is_first_entry(s, r.o, r.dir, r.te, r.dist, h));
    return true;
}

}  // namespace kerf::test

// Adaptive anti-aliasing's edge prediction (adaptive_aa.cpp, docs/quality.md):
// where an edge between two surfaces crosses a pixel's side, from the
// planes tangent to them at the side's two ends. A crease (a hole's rim:
// the plate's face meets the hole's wall) lies on both surfaces, so along
// the side the ray meets the one plane before the other up to the edge and
// after it beyond: the crossing is where the two planes' depths are equal.
// Over one pixel both surfaces are nearly their tangent planes, so that
// predicts the edge; the caller confirms it with a sample on either side
// (one, where the prediction is exact) and falls back to bisection where
// one disagrees (an occluding edge, where the depth jumps, or a surface
// that bends within the pixel).
#pragma once
#include <cmath>
#include <optional>

#include <glm/glm.hpp>

#include "render/primitives/primitives.hpp"

namespace kerf::render {

struct TangentPlane {
    glm::dvec3 point, normal;
};

// The side runs from the ray (o0, d0) at 0 to (o1, d1) at 1, as a camera's
// rays run between two neighbouring image points; `p` is the plane seen at
// 0, `q` at 1. g(o, d) = (n_p·(x_p − o))(n_q·d) − (n_q·(x_q − o))(n_p·d) is
// (t_p − t_q)(n_p·d)(n_q·d), t the ray's depth at each plane: it is 0
// where the depths are equal, and linear along the side for a pinhole
// (fixed o, d linear) and an orthographic camera (o linear, fixed d), so
// its root is exact there for two planes. Nothing where it has no root
// strictly inside the side.
inline std::optional<double> predicted_crossing(const glm::dvec3& o0, const glm::dvec3& d0, const glm::dvec3& o1,
                                                const glm::dvec3& d1, const TangentPlane& p, const TangentPlane& q) {
    const auto g = [&](const glm::dvec3& o, const glm::dvec3& d) {
        return glm::dot(p.normal, p.point - o) * glm::dot(q.normal, d) -
               glm::dot(q.normal, q.point - o) * glm::dot(p.normal, d);
    };
    const double g0 = g(o0, d0), g1 = g(o1, d1);
    if (!(g0 * g1 < 0)) return std::nullopt;  // no sign change (or a NaN): no crossing between the ends
    const double s = g0 / (g0 - g1);
    if (!(s > 0 && s < 1)) return std::nullopt;
    return s;
}

// Where the point plane `p` puts on the side's rays crosses a surface
// given by its signed distance (`distance(world point)`, negative inside,
// continuous): the edge where that surface cuts p's face (a hole's rim,
// near or far: the plate's face and the hole's cylinder), whether the
// corner across the edge sees that surface at the edge (a crease) or
// further away (an occluding edge). Regula falsi (Illinois), no rays, to
// 1/1,024 of the side (the samples that confirm it are 1/32 off it; each
// step costs a distance, ~20 % of a side's rays in all at 1/10,000);
// nothing where the distance keeps its sign (or is
// not finite: a mesh) between the ends.
template <class Distance>
std::optional<double> crossing_on_plane(const glm::dvec3& o0, const glm::dvec3& d0, const glm::dvec3& o1,
                                        const glm::dvec3& d1, const TangentPlane& p, Distance&& distance) {
    const auto f = [&](double s) {
        const glm::dvec3 o = glm::mix(o0, o1, s), d = glm::mix(d0, d1, s);
        return distance(o + glm::dot(p.normal, p.point - o) / glm::dot(p.normal, d) * d);
    };
    double a = 0, b = 1, fa = f(0), fb = f(1);
    if (!std::isfinite(fa) || !std::isfinite(fb) || !(fa * fb < 0)) return std::nullopt;
    double s = b;
    for (int i = 0; i < 16 && std::abs(b - a) > 1.0 / 1024; ++i) {
        s = (a * fb - b * fa) / (fb - fa);
        const double fs = f(s);
        if (!std::isfinite(fs)) return std::nullopt;
        if (fs == 0) break;
        if (fs * fb < 0) a = b, fa = fb;
        else fa /= 2;  // the end kept twice: halve its weight (Illinois), else it converges from one side only
        b = s, fb = fs;
    }
    if (!(s > 0 && s < 1)) return std::nullopt;
    return s;
}

// crossing_on_plane()'s answer without its root-finding, where the points
// plane `p` puts on the side's rays lie on one straight line: the rays
// share their origin (o0 == o1: a pinhole's) or their direction (d0 == d1:
// an orthographic camera's). `spans(a, b, out)` gives the surface's solid
// along that line, a + u·(b − a), as csg::intersect_leaf gives a leaf's (at
// most 2 spans, exact ends, u in [0, 1] asked for): a crossing where
// exactly one end of the line lies inside (crossing_on_plane()'s change of
// sign), at the first span end inside the line: exact, where regula falsi
// stopped within 1/1,024 of the side after ~6 distances (docs/quality.md,
// "The crossing from the leaf's own intervals"). `applies` false
// (crossing_on_plane() then answers): the points do not lie on a line, the
// plane is not in front at both ends, or a span ends within 1/65,536 of
// an end of the line, where whether that end lies inside is rounding's to
// say (an edge through a corner of the pixel, as at 45°), and the
// distance's sign says it as before.
struct LineCrossing {
    bool applies = false;
    std::optional<double> at;
    bool starts_inside = false;  // the line's end at 0 lies inside the surface's solid
    // Where `applies`: the line's ends (the points the plane puts on the
    // side's two rays) and their depths along those rays, t0 and t1, for
    // a caller that needs them too (the same numbers: not found again).
    glm::dvec3 from{0.0}, to{0.0};
    double t0 = 0, t1 = 0;
};
template <class Spans>
LineCrossing crossing_on_line(const glm::dvec3& o0, const glm::dvec3& d0, const glm::dvec3& o1, const glm::dvec3& d1,
                              const TangentPlane& p, Spans&& spans) {
    const bool pinhole = o0 == o1;
    if (!pinhole && d0 != d1) return {};
    const double t0 = glm::dot(p.normal, p.point - o0) / glm::dot(p.normal, d0),
                 t1 = glm::dot(p.normal, p.point - o1) / glm::dot(p.normal, d1);
    if (!(t0 > 0 && t1 > 0 && std::isfinite(t0) && std::isfinite(t1))) return {};
    csg::Span<double> out[csg::kMaxSpans];
    const glm::dvec3 from = o0 + t0 * d0, to = o1 + t1 * d1;
    const int n = spans(from, to, out);
    constexpr double kNear = 1.0 / 65536;
    bool inside0 = false, inside1 = false;
    double u = 1;
    for (int i = 0; i < n; ++i) {
        for (const double end : {out[i].t0, out[i].t1}) {
            // (A half-space's span has an infinite end: outside the line.)
            if (std::isnan(end) || std::abs(end) <= kNear || std::abs(end - 1) <= kNear) return {};
            if (end > 0 && end < u) u = end;
        }
        inside0 = inside0 || (out[i].t0 < 0 && 0 < out[i].t1);
        inside1 = inside1 || (out[i].t0 < 1 && 1 < out[i].t1);
    }
    if (inside0 == inside1) return {true, std::nullopt, inside0, from, to, t0, t1};
    // u along the line to s along the side: the ray at s, o + t(s)·d(s)
    // with d(s) = mix(d0, d1, s), meets the line at u = s·t0 / ((1 − s)·t1
    // + s·t0) for a shared origin (t0, t1: the plane's depths at the ends),
    // so s = u·t1 / ((1 − u)·t0 + u·t1); u = s for a shared direction.
    const double s = pinhole ? u * t1 / ((1 - u) * t0 + u * t1) : u;
    if (!(u < 1 && s > 0 && s < 1)) return {};
    return {true, s, inside0, from, to, t0, t1};
}

}  // namespace kerf::render

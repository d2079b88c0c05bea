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

}  // namespace kerf::render

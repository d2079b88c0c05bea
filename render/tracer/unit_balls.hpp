// A tight world-space ball around a unit of the root, when one is known
// cheaply: the unit's solid lies in its minuend (difference) or in each of
// its operands (intersection), and a sphere leaf is its own ball. The top
// BVH only box-tests units; in a crowd of overlapping cells the ray enters
// many boxes before the visible hit while missing most of their spheres, and
// each of those units cost a full evaluation (box, difference, minuend leaf
// transform, span push) to say "nothing here". The ball test says it with a
// few multiplies before any of that (first_hit.cpp, shadow_rays.cpp).
//
// Exactness: a ball is padded (build and per ray) beyond the round-off of
// the minuend's own interval test, so a rejected unit is one whose spans
// would all lie outside the window: the answer, and so the image, is the
// same; only the work (and the --stats counts) shrink.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "csg/scene.hpp"

namespace kerf::render {

struct Ball {
    glm::dvec3 c{0.0};
    double r = -1;  // < 0: none known (the unit is evaluated as before)
};

// A subtrahend of a sphere-minus-few unit (ball_chords.hpp): the ball around
// it, or else its box, and the ball inside it, if any (a sphere leaf).
struct SubBound {
    glm::dvec3 c{0.0};
    double r_out = -1;  // < 0: its outer bound is `box`
    double r_in = -1;   // < 0: nothing known inside it
    csg::Aabb box;      // its bounds grown by the unit's degenerate rule
};

// A unit that is a sphere leaf minus at most kMaxSubs other nodes: the
// sphere's inner ball (the outer one is the unit's Ball) and its
// subtrahends' bounds at subs[first..first+count).
struct SphereMinus {
    double r_in = -1;  // < 0: not such a unit
    std::uint32_t first = 0, count = 0;
    static constexpr std::uint32_t kMaxSubs = 8;  // more: an own BVH, left to it
};

// Per unit (in `units` order), padded by `pad[unit]` (world length). Empty
// when no unit has a ball, or only leaves do (a leaf's ball test would
// duplicate its own interval test): scenes without such units pay nothing.
// `leaves`: sphere leaves get their balls too (a crowd of bare spheres,
// build.cpp: the balls bring tile culling and ray cones).
std::vector<Ball> unit_balls(const csg::Scene& scene, const std::vector<std::uint32_t>& units,
                             const std::vector<double>& pad, bool leaves = false);

// Per unit (in `units` order) its SphereMinus, with the subtrahends appended
// to `subs`; balls shrunk (inner) or grown (outer) by the same padding as
// unit_balls. Empty when no unit is one.
std::vector<SphereMinus> sphere_minus_units(const csg::Scene& scene, const std::vector<std::uint32_t>& units,
                                            const std::vector<double>& pad, std::vector<SubBound>& subs);

// A unit's ball as a ray's own tests grow it: slack_abs for the ray's
// origin magnitude (4·eps_ray), slack_rel per unit of w1 = |c - o|₁. One
// formula for every test that must keep what another keeps (ball_misses,
// the outer chord, tile culling's bound over a tile's rays).
inline double grown_radius(double r, double slack_abs, double slack_rel, double w1) {
    return r + slack_abs + slack_rel * w1;
}

// ball_misses' test from w = c - o and the grown radius squared (rr2):
// the terms that depend on the ray's origin alone, which a camera's rays
// can take from their apex (Apex::at_p; the same numbers).
inline bool ball_misses_from(const glm::dvec3& w, double rr2, const glm::dvec3& d, double inv_len2, double a, double b) {
    const double tc = glm::dot(w, d) * inv_len2;
    const glm::dvec3 c0 = w - tc * d;  // from the line's closest point to the centre
    const double h2 = (rr2 - glm::dot(c0, c0)) * inv_len2;
    // The chord [tc - h, tc + h] misses [a, b] when the window's gap to tc
    // (positive on at most one side) exceeds h: squared, so no square root
    // (the pad above dwarfs the rounding either form has), and by one
    // comparison (gap·|gap| is negative when tc lies in the window; NaN
    // and h² <= 0 miss).
    const double gap = std::max(a - tc, tc - b);
    return !(std::min(h2, h2 - gap * std::abs(gap)) > 0);
}

// True if the segment [a, b] of o + t·d is provably outside `ball`: the
// line misses it or its chord lies wholly before a or after b. inv_len2 =
// 1/|d|²; slack_abs: world padding for the ray's origin magnitude; slack_rel:
// relative round-off of the leaf's own test (float or double) per unit of
// |c - o|.
inline bool ball_misses(const Ball& ball, const glm::dvec3& o, const glm::dvec3& d, double inv_len2, double a,
                        double b, double slack_abs, double slack_rel) {
    const glm::dvec3 w = ball.c - o;
    const double r = grown_radius(ball.r, slack_abs, slack_rel, std::abs(w.x) + std::abs(w.y) + std::abs(w.z));
    return ball_misses_from(w, r * r, d, inv_len2, a, b);
}

}  // namespace kerf::render

// Bounds on a sphere-minus-few unit (unit_balls.hpp, SphereMinus: a cell,
// a shell segment) along one ray from the chords of its balls alone, before
// any of its evaluation: in a crowd of overlapping cells most units the ray
// crosses before its visible hit are entered through their hollow, and the
// chords prove it with a few multiplies (README.md, "Ball chords").
//
// Each ball is padded beyond the round-off of the leaves' own interval
// tests (the same padding as the unit balls, grown for an outer ball and
// shrunk for an inner one, plus the round-off of the chord itself), so:
// - the minuend's computed span lies inside its outer chord and holds its
//   inner chord, and the same for each subtrahend (a subtrahend that is not
//   a sphere leaf: its box chord outside, nothing inside);
// - so no piece of the unit starts (or overlaps the window) where the
//   subtrahends' inner chords cover the minuend's outer chord: the lower
//   bound;
// - and a stretch of the minuend's inner chord clear of every subtrahend's
//   outer chord, longer than twice the degenerate rule, lies in a piece the
//   exact evaluation keeps: the upper bound, and a proven shadow.
// The answers the callers take from these are the ones the exact
// evaluation gives; only the work shrinks.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/tracer/ray_state.hpp"

namespace kerf::render {

struct Chord {
    double t0, t1;  // empty unless t0 <= t1
};
constexpr Chord kNoChord{kInf, -kInf};

namespace ball_chords_detail {

// Where a ball's centre lies from the ray: the outer and inner chords of
// any radius follow from these.
struct Centre {
    double tc, q2, w1;
};

// (w = c - o, w1 = |w|₁.)
[[gnu::always_inline]] inline Centre centre_of(const RayState& st, double wx, double wy, double wz, double w1,
                                               double inv_len2) {
    Centre k;
    k.tc = (wx * st.d.x + wy * st.d.y + wz * st.d.z) * inv_len2;
    const double cx = wx - k.tc * st.d.x, cy = wy - k.tc * st.d.y, cz = wz - k.tc * st.d.z;
    k.q2 = cx * cx + cy * cy + cz * cz;
    k.w1 = w1;
    return k;
}

[[gnu::always_inline]] inline Centre centre(const RayState& st, const glm::dvec3& c, double inv_len2) {
    const double wx = c.x - st.o.x, wy = c.y - st.o.y, wz = c.z - st.o.z;
    return centre_of(st, wx, wy, wz, std::abs(wx) + std::abs(wy) + std::abs(wz), inv_len2);
}

// Outer (grow = +1) or inner (grow = -1) chord of the ball of radius r
// around k, padded per ray by the origin's rule and the relative round-off;
// the last term bounds the round-off of r² - |c0|² (it matters at grazing
// chords; w1² >= |w|²).
[[gnu::always_inline]] inline Chord chord(const Centre& k, double r, double grow, double slack_abs, double slack_rel,
                                          double inv_len2) {
    Chord ch = kNoChord;
    if (!(r > 0)) return ch;
    const double rr = r + grow * (slack_abs + slack_rel * k.w1);
    if (!(rr > 0)) return ch;
    const double h2 = (rr * rr - k.q2 + grow * 1e-13 * (k.w1 * k.w1 + rr * rr)) * inv_len2;
    if (!(h2 > 0)) return ch;
    const double h = std::sqrt(h2);
    ch.t0 = k.tc - h;
    ch.t1 = k.tc + h;
    return ch;
}

}  // namespace ball_chords_detail

// The chords of a unit's balls along the state's ray, in two halves: the
// lower bound's (the minuend's outer chord, the subtrahends' inner ones)
// first, since most units the traversal meets are dropped by it (entered
// through their hollow, or starting past the best entry), and the upper
// bound's (the minuend's inner chord, the subtrahends' outer ones) only for
// the rest: half the square roots for a dropped unit. (Left uninitialised:
// each half writes what is read.)
struct UnitChords {
    Chord m_out, m_in;  // the minuend sphere
    Chord s_out[SphereMinus::kMaxSubs], s_in[SphereMinus::kMaxSubs];
    ball_chords_detail::Centre m, s[SphereMinus::kMaxSubs];  // where the balls' centres lie
    std::uint32_t item, node, n;
    double eps;  // the unit's degenerate rule (t), set with the upper half
};

// Whether the outer chord of unit `item`'s ball (its minuend's) reaches
// the window [a, b]; m and h2 (its squared half-length in t) are set for
// unit_chords when it does. Most units the ray's box test lets through miss
// here: decided without the square root (h < a - tc, h < tc - b), whose
// latency was most of their cost, and by one branch, whose outcome no
// predictor can guess: the window's gap to tc is positive on at most one
// side; gap·|gap| is its square there and negative when tc lies in the
// window, so min(h², h² - gap·|gap|) > 0 says "the chord reaches the
// window" (NaN and h² <= 0 miss). Inline and apart from unit_chords, so a
// miss costs its callback no more than this (large shell: two camera-ray
// callbacks in three end here, and 93 % of the shadow rays').
[[gnu::always_inline]] inline bool outer_chord_reaches(const RayState& st, std::uint32_t item, double a, double b,
                                                       ball_chords_detail::Centre& m, double& h2) {
    const CsgTracer::Impl& impl = *st.impl;
    const double inv_len2 = st.inv_len * st.inv_len;
    const Ball& ball = impl.top.balls[item];
    m = ball_chords_detail::centre(st, ball.c, inv_len2);
    const double rr = grown_radius(ball.r, 4 * st.eps_ray, impl.ball_slack, m.w1);
    h2 = (rr * rr - m.q2 + 1e-13 * (m.w1 * m.w1 + rr * rr)) * inv_len2;
    const double gap = std::max(a - m.tc, m.tc - b);
    return std::min(h2, h2 - gap * std::abs(gap)) > 0;
}

// The same for a ray that starts exactly at a camera apex, with the terms
// that depend on its origin alone found once (Apex::AtP): the same numbers.
[[gnu::always_inline]] inline bool outer_chord_reaches(const RayState& st, const Apex::AtP& at, double a, double b,
                                                       ball_chords_detail::Centre& m, double& h2) {
    const double inv_len2 = st.inv_len * st.inv_len;
    m = ball_chords_detail::centre_of(st, at.w.x, at.w.y, at.w.z, at.w1, inv_len2);
    h2 = (at.rr2 - m.q2 + at.round) * inv_len2;
    const double gap = std::max(a - m.tc, m.tc - b);
    return std::min(h2, h2 - gap * std::abs(gap)) > 0;
}

// The lower half of the chords of unit `item` of the top BVH (which has a
// SphereMinus) for the window [a, b], after outer_chord_reaches gave m and
// h2. False, with the rest not computed, when the minuend's outer chord
// misses the window (the unit has no span there).
inline bool unit_chords(const RayState& st, std::uint32_t item, std::uint32_t node, double a, double b,
                        const ball_chords_detail::Centre& m, double h2, UnitChords& u) {
    using namespace ball_chords_detail;
    const CsgTracer::Impl& impl = *st.impl;
    const double inv_len2 = st.inv_len * st.inv_len, slack_abs = 4 * st.eps_ray, rel = impl.ball_slack;
    // (chord()'s sum for the outer ball, grouped as outer_chord_reaches does.)
    const double h = std::sqrt(h2);
    u.m_out = Chord{m.tc - h, m.tc + h};
    if (!(u.m_out.t0 <= b && u.m_out.t1 >= a)) return false;
    const SphereMinus& sm = impl.top.sphere_minus[item];
    u.m = m;
    u.item = item;
    u.node = node;
    u.n = sm.count;
    for (std::uint32_t k = 0; k < sm.count; ++k) {
        const SubBound& s = impl.top.subs[sm.first + k];
        if (s.r_out >= 0) {
            u.s[k] = centre(st, s.c, inv_len2);
            u.s_in[k] = chord(u.s[k], s.r_in, -1, slack_abs, rel, inv_len2);
        } else {
            u.s_in[k] = kNoChord;
        }
    }
    return true;
}

// The upper half: the minuend's inner chord and the subtrahends' outer
// chords (unit_chords first).
[[gnu::always_inline]] inline void unit_chords_upper(const RayState& st, UnitChords& u) {
    using namespace ball_chords_detail;
    const CsgTracer::Impl& impl = *st.impl;
    const double inv_len2 = st.inv_len * st.inv_len, slack_abs = 4 * st.eps_ray, rel = impl.ball_slack;
    const SphereMinus& sm = impl.top.sphere_minus[u.item];
    u.eps = (impl.node_eps[u.node] + st.eps_ray) * st.inv_len;
    u.m_in = chord(u.m, sm.r_in, -1, slack_abs, rel, inv_len2);
    for (std::uint32_t k = 0; k < sm.count; ++k) {
        const SubBound& s = impl.top.subs[sm.first + k];
        if (s.r_out >= 0) {
            u.s_out[k] = chord(u.s[k], s.r_out, 1, slack_abs, rel, inv_len2);
            continue;
        }
        // The box's chord, grown by the same per-ray slack (in t).
        double t0 = -kInf, t1 = kInf;
        if (!slab_clip(s.box, st.o, st.invd, t0, t1)) {
            u.s_out[k] = kNoChord;
            continue;
        }
        const glm::dvec3 w = 0.5 * (s.box.lo + s.box.hi) - st.o;
        const double pad =
            4 * u.eps + (slack_abs + rel * (std::abs(w.x) + std::abs(w.y) + std::abs(w.z))) * st.inv_len;
        u.s_out[k] = Chord{t0 - pad, t1 + pad};
    }
}

// x moved past every chord of cs[0..n) that holds it (again and again:
// the chords may chain).
inline double past_chords(const Chord* cs, std::uint32_t n, double x) {
    if (n == 1) return cs[0].t0 <= x && cs[0].t1 > x ? cs[0].t1 : x;  // a cell: one hollow
    for (std::uint32_t pass = 0; pass < n; ++pass) {
        bool moved = false;
        for (std::uint32_t k = 0; k < n; ++k)
            if (cs[k].t0 <= x && cs[k].t1 > x) {
                x = cs[k].t1;
                moved = true;
            }
        if (!moved) break;
    }
    return x;
}

// No piece of the unit starts in (a, lower) or lies in [a, lower): the
// first point of the minuend's outer chord on [a, b] that the subtrahends'
// inner chords leave uncovered; kInf when they cover all of it (then the
// unit has no span overlapping [a, b]).
inline double chords_lower(const UnitChords& u, double a, double b) {
    const double lo = std::max(a, u.m_out.t0), hi = std::min(b, u.m_out.t1);
    if (!(lo <= hi)) return kInf;
    const double x = past_chords(u.s_in, u.n, lo);
    return x > hi ? kInf : x;
}

// The start of the first stretch of the minuend's inner chord on (a, b)
// that no subtrahend's outer chord touches and that is longer than 2·eps
// (a piece of the unit holds it); kInf when none is found. (unit_chords_upper
// first.)
inline double chords_inside(const UnitChords& u, double a, double b) {
    double x = std::max(a, u.m_in.t0);
    const double end = std::min(b, u.m_in.t1);
    for (std::uint32_t guard = 0; guard <= u.n && x < end; ++guard) {
        x = past_chords(u.s_out, u.n, x);
        if (!(x < end)) break;
        double next = end;
        for (std::uint32_t k = 0; k < u.n; ++k)
            if (u.s_out[k].t0 > x) next = std::min(next, u.s_out[k].t0);
        if (next - x > 2 * u.eps) return x;
        x = next;
    }
    return kInf;
}

// An upper bound on the unit's first entry after a (the entry try_unit_entry
// finds), or kInf: a stretch inside the unit, on a ray that is outside the
// minuend's outer chord just after a (so the piece holding the stretch
// starts after a).
inline double chords_upper(const RayState& st, UnitChords& u, double a, double b) {
    if (!(u.m_out.t0 > a)) return kInf;
    unit_chords_upper(st, u);
    return chords_inside(u, a, b);
}

// Whether the unit's first entry after a, when it has one on the window,
// is its minuend's own entry, found by the minuend's leaf test alone (after
// chords_upper gave a bound, so the ray is outside the minuend's outer
// chord just after a). The minuend's computed span [t0, t1] holds its inner
// chord and lies in its outer one, so t0 lies in [m_out.t0, m_in.t0] and
// t1 - t0 exceeds the inner chord's length; when that is more than 2·eps
// and no subtrahend's outer chord (which holds its computed spans) touches
// [m_out.t0, m_in.t0 + 2·eps], every subtraction the exact evaluation makes
// (the clearance fast path, its near subtrahends, the full gather) leaves
// the piece [t0, ...) with the minuend's t0 and end: span_difference keeps a
// piece's start when no subtrahend span begins within eps of it.
inline bool entry_is_minuends(const UnitChords& u) {
    if (!(u.m_in.t1 - u.m_in.t0 > 2 * u.eps)) return false;
    const double lo = u.m_out.t0, hi = u.m_in.t0 + 2 * u.eps;
    for (std::uint32_t k = 0; k < u.n; ++k)
        if (u.s_out[k].t0 <= hi && u.s_out[k].t1 >= lo) return false;
    return true;
}

}  // namespace kerf::render

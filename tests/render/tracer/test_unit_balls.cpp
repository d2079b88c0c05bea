// Units of the root whose solid lies in a sphere (a difference with a
// sphere minuend, an intersection with a sphere operand) are rejected by
// that ball before any evaluation (render/tracer/unit_balls.hpp). The
// rejection must never drop a hit: here a crowd of such units, under
// rotations, non-uniform scales and mirrors, is shot with rays aimed at
// points just inside and just outside their spheres' surfaces (grazing the
// balls), and every answer of intersect() and occluded() is checked against
// point membership along the ray (no ray code). A ball that is too small, or
// a stretch bound below the true one, shows as a missed or late entry.
//
// Units that are a sphere minus a few spheres or small boxes (cells, shell
// segments) are also bounded by the chords of their balls and evaluated
// after the traversal nearest bound first (render/tracer/ball_chords.hpp).
// A crowd of overlapping hollow cells (inner spheres poking out of the
// outer ones: openings) is shot the same way, at the inner spheres' surfaces
// too and also from points inside the crowd (the ray starts in the hollows,
// inside outer balls). An inner chord that is not shrunk, or an outer one
// not grown, shows as a missed or late entry or a wrong shadow.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "render/tracer/tracer.hpp"
#include "tests/render/random_csg.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;
using csg::PrimKind;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Crowd {
    Tree tree = op(Op::Union, {});
    std::vector<glm::dmat4> ball_from_unit;  // world_from_object of spheres to aim at (radius 1)
    // cells: maps the unit circle in z = 0 onto a rim where a subtrahend
    // sphere cuts its minuend's (the edge of an opening)
    std::vector<glm::dmat4> rim_from_circle;
    std::vector<glm::dmat4> rim_minuend;  // per rim: its minuend's world_from_object (centre at the origin)
};

// The circle where the sphere of radius ri around `off` cuts the one of
// radius r around the origin, as the map of the unit circle in z = 0 onto
// it; false when they do not cut.
bool rim_circle(double r, double ri, const glm::dvec3& off, glm::dmat4& f) {
    const double dist = glm::length(off);
    if (!(dist > 1e-9)) return false;
    const double x = (dist * dist + r * r - ri * ri) / (2 * dist);
    if (!(r * r - x * x > 0)) return false;
    const double a = std::sqrt(r * r - x * x);
    const glm::dvec3 w = off / dist;
    const glm::dvec3 u = glm::normalize(glm::cross(w, std::abs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 v = glm::cross(w, u);
    f = glm::dmat4(glm::dvec4(a * u, 0), glm::dvec4(a * v, 0), glm::dvec4(w, 0), glm::dvec4(x * w, 1));
    return true;
}

// A random placement near `at`: rotation, scale in [lo, 1.2] per axis
// (sometimes mirrored; uniform when `similar`), and the radius r of the
// sphere placed with it.
glm::dmat4 placement(RandomCsg& g, const glm::dvec3& at, double lo, bool (*similar)(RandomCsg&), double& r) {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
    glm::dvec3 s(g.uni(lo, 1.2), g.uni(lo, 1.2), g.uni(lo, 1.2));
    if (g.pick(5) == 0) s.x = -s.x;
    if (similar(g)) s = glm::dvec3(s.y);
    r = g.uni(0.3, 0.6);
    return translate(at.x + g.uni(-1, 1), at.y + g.uni(-1, 1), at.z + g.uni(-1, 1)) *
           rotate_deg(g.uni(0, 360), axis) * scale(s.x, s.y, s.z);
}

// 40 overlapping units around `at`: sphere minus a smaller offset solid,
// sphere ∩ box, and a few plain leaves.
Crowd crowd(RandomCsg& g, const glm::dvec3& at) {
    Crowd c;
    for (int k = 0; k < 40; ++k) {
        // Similarity transforms too (the exact stretch).
        double r;
        const glm::dmat4 m = placement(g, at, 0.3, [](RandomCsg& q) { return q.pick(3) == 0; }, r);
        c.ball_from_unit.push_back(m * scale(r, r, r));
        const csg::Leaf outer = sphere(r, m);
        const int kind = g.pick(10);
        if (kind < 6) {
            const glm::dvec3 off(g.uni(-0.3, 0.3) * r, g.uni(-0.3, 0.3) * r, g.uni(-0.3, 0.3) * r);
            const csg::Leaf inner = g.pick(2) == 0 ? sphere(0.8 * r, m * translate(off.x, off.y, off.z))
                                                   : box(-0.6 * r + off, 0.6 * r + off, m);
            c.tree.kids.push_back(op(Op::Difference, {leaf(outer), leaf(inner)}));
        } else if (kind < 9) {
            const glm::dvec3 h(g.uni(0.4, 1.2) * r);
            c.tree.kids.push_back(op(Op::Intersection, {leaf(box(-h, h, m)), leaf(outer)}));
        } else {
            c.tree.kids.push_back(leaf(outer));
        }
    }
    return c;
}

// 60 overlapping cells around `at`: a sphere minus 1-3 smaller spheres,
// offset so that some break through (a cup), sometimes a small box too;
// the whole crowd scaled by `size` about `at`.
Crowd cells_of_size(RandomCsg& g, const glm::dvec3& at, double size) {
    Crowd c;
    const glm::dmat4 world = translate(at.x, at.y, at.z) * scale(size, size, size) * translate(-at.x, -at.y, -at.z);
    for (int k = 0; k < 60; ++k) {
        // Mostly similarities: the chords' usual case.
        double r;
        const glm::dmat4 m = world * placement(g, at, 0.6, [](RandomCsg& q) { return q.pick(3) != 0; }, r);
        std::vector<Tree> kids{leaf(sphere(r, m))};
        c.ball_from_unit.push_back(m * scale(r, r, r));
        const int holes = 1 + g.pick(3);
        for (int h = 0; h < holes; ++h) {
            const double ri = g.uni(0.5, 0.9) * r;
            const glm::dvec3 off(g.uni(-0.3, 0.3) * r, g.uni(-0.3, 0.3) * r, g.uni(-0.3, 0.3) * r);
            const glm::dmat4 mi = m * translate(off.x, off.y, off.z);
            kids.push_back(leaf(sphere(ri, mi)));
            c.ball_from_unit.push_back(mi * scale(ri, ri, ri));
            if (glm::dmat4 f; rim_circle(r, ri, off, f)) {
                c.rim_from_circle.push_back(m * f);
                c.rim_minuend.push_back(m);
            }
        }
        if (g.pick(4) == 0) {
            const glm::dvec3 off(g.uni(-0.5, 0.5) * r, g.uni(-0.5, 0.5) * r, g.uni(-0.5, 0.5) * r);
            kids.push_back(leaf(box(off - 0.2 * r, off + 0.2 * r, m)));
        }
        c.tree.kids.push_back(op(Op::Difference, kids));
    }
    return c;
}

Crowd cells(RandomCsg& g, const glm::dvec3& at) { return cells_of_size(g, at, 1); }

// 40 lenses around `at`: two spheres intersected (thin and fat lenses,
// unequal radii, caps more and less than a hemisphere), under
// similarities (mirrors too). A lens of two balls lies in the ball on their
// circle of intersection (unit_balls.cpp, lens_ball), which the solid
// touches along its rim: ball_from_unit maps the unit sphere onto it, its
// equator onto the rim.
Crowd lenses(RandomCsg& g, const glm::dvec3& at) {
    Crowd c;
    for (int k = 0; k < 40; ++k) {
        double r;
        const glm::dmat4 m = placement(g, at, 0.6, [](RandomCsg&) { return true; }, r);
        // Centres apart by more than the radii's difference (a rim circle
        // exists) and less than their sum, a tenth of the smaller radius
        // from either.
        const double r2 = r * g.uni(0.7, 1.3), e = 0.1 * std::min(r, r2);
        const double d = g.uni(std::abs(r - r2) + e, r + r2 - e);
        c.tree.kids.push_back(op(Op::Intersection, {leaf(sphere(r, m)), leaf(sphere(r2, m * translate(0, 0, d)))}));
        const double x = (d * d + r * r - r2 * r2) / (2 * d), a = std::sqrt(std::max(0.0, r * r - x * x));
        c.ball_from_unit.push_back(m * translate(0, 0, x) * scale(a, a, a));
    }
    return c;
}

// One ray along o + t·d (unit d) checked against point membership: its
// first entry, a shadow-style query on (0, tfar) and one towards a light
// beyond the crowd. Returns 1 if it hits. h_thin > 0: an entry into a
// sliver thinner than h (a ray through the edge of an opening) may be
// checked at that finer step instead.
int check_ray(const csg::Scene& s, const render::CsgTracer& tracer, render::TraceScratch& scratch, const glm::dvec3& o,
              const glm::dvec3& d, double tfar, double h, bool use_float, double h_thin = 0) {
    render::TraceHit hit;
    const double t = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) ? hit.t : kInf;
    INFO("first entry " << t);
    CHECK((is_first_entry(s, o, d, t, 14, h) || (h_thin > 0 && is_first_entry(s, o, d, t, 14, h_thin))));
    // Shadow-style query on (0, tfar): blocked exactly when the first
    // entry comes before tfar (the ray starts outside the solid).
    if (tfar > 0 && std::abs(t - tfar) > (use_float ? 100 * h : 1e-6))
        CHECK(tracer.occluded(render::TraceRay{o, d, 0, tfar}, scratch) == (t < tfar));
    // And towards a light beyond the crowd (the ball BVH's shadow path,
    // also from inside the balls): blocked exactly when there is an entry.
    CHECK(tracer.occluded(render::TraceRay{o, d, 0, 100}, scratch) == std::isfinite(t));
    return std::isfinite(t) ? 1 : 0;
}

// Shoots 400 rays at the crowd `make` builds: aim(g, crowd, scene, i, o,
// d, tfar) gives ray i (false: none) and checks it (check_ray); returns how
// many of them hit.
template <class Aim>
int shoot(std::uint64_t seed, const glm::dvec3& at, double h, Crowd (*make)(RandomCsg&, const glm::dvec3&),
          bool use_float, Aim&& aim) {
    RandomCsg g(seed);
    const Crowd c = make(g, at);
    const csg::Scene s = make_scene(c.tree);
    const render::CsgTracer tracer(s, use_float);
    render::TraceScratch scratch;
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        glm::dvec3 o, d;
        double tfar;
        if (!aim(g, c, s, i, o, d, tfar)) continue;
        INFO("seed " << seed << " ray " << i);
        hits += check_ray(s, tracer, scratch, o, d, tfar, h, use_float);
    }
    return hits;
}

// Rays onto points within ±band (2 %) of a unit sphere's surface, from 6 units
// away (plus `at`) or, with `from_inside`, every other one from a point in
// the crowd outside the solid; returns how many of them hit.
int check_crowd(std::uint64_t seed, const glm::dvec3& at, double h, Crowd (*make)(RandomCsg&, const glm::dvec3&),
                bool from_inside, bool use_float = false, double band = 0.02) {
    return shoot(seed, at, h, make, use_float, [&](RandomCsg& g, const Crowd& c, const csg::Scene& s, int i,
                                                   glm::dvec3& o, glm::dvec3& d, double& tfar) {
        const glm::dvec3 u = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
        const glm::dmat4& m = c.ball_from_unit[std::size_t(g.pick(int(c.ball_from_unit.size())))];
        const glm::dvec3 target = glm::dvec3(m * glm::dvec4(g.uni(1 - band, 1 + band) * u, 1.0));
        const glm::dvec3 dir = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
        o = from_inside && i % 2 == 1 ? at + g.uni(0, 1.5) * dir : at + 6.0 * dir;
        if (csg_contains(s, o) || glm::length(target - o) < 1e-3) return false;
        d = glm::normalize(target - o);
        tfar = glm::length(target - o) + g.uni(-0.3, 0.3);
        return true;
    });
}

// Rays that graze the rims of a crowd of lenses: in the plane of a lens's
// rim (tilted by up to 1e-3), passing within 0.2 % of its radius inside the
// rim circle, so they meet the lens in its thin edge and pass within 0.2 %
// of its ball's surface; returns how many of them hit.
int check_lens_rims(std::uint64_t seed, const glm::dvec3& at, double h) {
    return shoot(seed, at, h, lenses, false, [](RandomCsg& g, const Crowd& c, const csg::Scene& s, int,
                                                glm::dvec3& o, glm::dvec3& d, double& tfar) {
        const glm::dmat4& m = c.ball_from_unit[std::size_t(g.pick(int(c.ball_from_unit.size())))];
        const double th = g.uni(0, 2 * M_PI), inside = 1 - g.uni(0, 2e-3);
        const glm::dvec3 p(m * glm::dvec4(inside * std::cos(th), inside * std::sin(th), 0, 1));
        d = glm::normalize(glm::dvec3(m * glm::dvec4(-std::sin(th), std::cos(th), g.uni(-1e-3, 1e-3), 0)));
        o = p - 6.0 * d;
        tfar = 6.0 + g.uni(-0.3, 0.3);
        return !csg_contains(s, o);
    });
}

// Rays through the rims of a crowd of cells of `size` (the edges of their
// openings, within ±1e-4 of the cell's size), from outside in every
// direction, every other one grazing the minuend's sphere there; d has
// length `size`, so t counts in the crowd's units. There the
// minuend's entry and a subtrahend's surface meet: the ray enters the cell
// at the minuend's sphere or passes into the opening, and the chords must
// tell which before the leaf test alone answers (ball_chords.hpp,
// entry_is_minuends). A ray through the edge may clip a sliver of the cell
// thinner than h: its entry is checked at h / 100 too (the degenerate rule
// is ~1e-9 of the size, far below). Returns how many of them hit.
int check_rims(std::uint64_t seed, const glm::dvec3& at, double size, double h) {
    RandomCsg g(seed);
    const Crowd c = cells_of_size(g, at, size);
    REQUIRE(c.rim_from_circle.size() > 20);
    const csg::Scene s = make_scene(c.tree);
    const render::CsgTracer tracer(s, false);
    render::TraceScratch scratch;
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const std::size_t k = std::size_t(g.pick(int(c.rim_from_circle.size())));
        const glm::dmat4& f = c.rim_from_circle[k];
        const double th = g.uni(0, 2 * M_PI), out = 1 + g.uni(-1e-4, 1e-4);
        const glm::dvec4 q(out * std::cos(th), out * std::sin(th), g.uni(-1e-4, 1e-4), 1);
        const glm::dvec3 p(f * q);
        glm::dvec3 dir = glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3;
        if (i % 2 == 1) {
            // Grazing: tangent to the minuend's sphere at the rim (tilted by
            // up to 1e-3 into it), so its entry stretch is long and the
            // subtrahend's surface crosses it.
            const glm::dvec3 at_rim = glm::dvec3(glm::inverse(c.rim_minuend[k]) * glm::dvec4(p, 1));
            const glm::dvec3 n = glm::normalize(at_rim);
            const glm::dvec3 t = glm::normalize(glm::cross(n, dir)) - g.uni(0, 1e-3) * n;
            dir = glm::dvec3(c.rim_minuend[k] * glm::dvec4(t, 0));
        }
        const glm::dvec3 d = size * glm::normalize(dir);
        const glm::dvec3 o = p - 6.0 * d;
        if (csg_contains(s, o)) continue;
        INFO("seed " << seed << " ray " << i);
        hits += check_ray(s, tracer, scratch, o, d, 6.0 + g.uni(-0.3, 0.3), h, false, h / 100);
    }
    return hits;
}

}  // namespace

TEST_CASE("unit balls: rays grazing a crowd of sphere-bounded units keep every entry and every shadow",
          "[render][oracle]") {
    int hits = 0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) hits += check_crowd(seed, glm::dvec3(0.0), 1e-7, crowd, false);
    CHECK(hits > 400);  // the rays do reach the crowd (not all background)
}

// Far from the origin the ray's own round-off grows (the slack for |o|).
TEST_CASE("unit balls far from the origin keep every entry too", "[render][oracle]") {
    const glm::dvec3 at = 1e6 * glm::normalize(glm::dvec3(1, -0.6, 0.3));
    int hits = 0;
    for (std::uint64_t seed = 11; seed <= 12; ++seed) hits += check_crowd(seed, at, 1e-6, crowd, false);
    CHECK(hits > 200);
}

TEST_CASE("ball chords: rays into a crowd of hollow cells keep every entry and every shadow", "[render][oracle]") {
    int hits = 0;
    for (std::uint64_t seed = 21; seed <= 24; ++seed) hits += check_crowd(seed, glm::dvec3(0.0), 1e-7, cells, true);
    CHECK(hits > 500);
}

TEST_CASE("ball chords far from the origin keep every entry too", "[render][oracle]") {
    const glm::dvec3 at = 1e6 * glm::normalize(glm::dvec3(-0.4, 1, 0.7));
    int hits = 0;
    for (std::uint64_t seed = 31; seed <= 32; ++seed) hits += check_crowd(seed, at, 1e-6, cells, true);
    CHECK(hits > 250);
}

// The float path pads by its own round-off (ball_slack 1e-5 of |c - o|).
TEST_CASE("ball chords on the float path keep every entry too", "[render][oracle]") {
    int hits = 0;
    for (std::uint64_t seed = 41; seed <= 42; ++seed) hits += check_crowd(seed, glm::dvec3(0.0), 1e-4, cells, true, true);
    CHECK(hits > 250);
}

// Camera rays from outside the crowd go through the units' balls as
// Embree's float spheres (render/tracer/build.cpp, "Ball BVH"): rays grazing
// the balls within ±0.01 % of their radius find every entry and every shadow
// (a sphere 0.1 % too small fails here).
TEST_CASE("ball BVH: camera rays grazing a crowd of cells keep every entry", "[render][oracle]") {
    int hits = 0;
    for (std::uint64_t seed = 51; seed <= 54; ++seed)
        hits += check_crowd(seed, glm::dvec3(0.0), 1e-7, cells, false, false, 1e-4);
    CHECK(hits > 500);
}

// Lens-shaped units (sphere ∩ sphere) are rejected by the smaller ball on
// their rim (unit_balls.cpp, lens_ball): rays at points within ±2 % of that
// ball, and rays that graze the rims inside it by up to 0.2 %, keep every
// entry and every shadow (a lens ball 0.1 % too small fails here).
TEST_CASE("unit balls: rays grazing the rims of a crowd of lenses keep every entry and every shadow",
          "[render][oracle]") {
    int hits = 0, rims = 0;
    for (std::uint64_t seed = 61; seed <= 63; ++seed) {
        hits += check_crowd(seed, glm::dvec3(0.0), 1e-7, lenses, true);
        rims += check_lens_rims(seed + 10, glm::dvec3(0.0), 1e-7);
    }
    CHECK(hits > 300);
    CHECK(rims > 600);
}

TEST_CASE("lens balls far from the origin keep every entry too", "[render][oracle]") {
    const glm::dvec3 at = 1e6 * glm::normalize(glm::dvec3(0.3, 0.8, -0.5));
    int rims = 0;
    for (std::uint64_t seed = 81; seed <= 82; ++seed) rims += check_lens_rims(seed, at, 1e-6);
    CHECK(rims > 400);
}

// A cell's first entry is taken from its minuend's leaf test alone when the
// chords prove no subtrahend near it (ball_chords.hpp, entry_is_minuends):
// rays through the edges of the openings, where that proof must fail, at
// unit size, tiny and huge, and far from the origin (taking the minuend's
// entry whenever the minuend's inner chord is long, subtrahends or not,
// fails here).
TEST_CASE("ball chords: rays through the rims of openings keep every entry and every shadow", "[render][oracle]") {
    int hits = 0;
    for (std::uint64_t seed = 91; seed <= 93; ++seed) hits += check_rims(seed, glm::dvec3(0.0), 1, 1e-7);
    hits += check_rims(94, glm::dvec3(0.0), 1e-4, 1e-7);
    hits += check_rims(95, glm::dvec3(0.0), 1e4, 1e-7);
    hits += check_rims(96, 1e6 * glm::normalize(glm::dvec3(0.5, -1, 0.2)), 1, 1e-6);
    CHECK(hits > 1200);
}

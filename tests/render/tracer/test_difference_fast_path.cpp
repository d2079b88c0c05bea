// A difference asked for its first entry (camera rays) or for any span
// (shadow rays) skips its subtrahends when the minuend's point is provably
// clear of them (render/clearance.cpp). Here every subtrahend kind, under a
// rotation, non-uniform scale and translation, cuts the top face of a box
// minuend, and rays land all over that face — inside, outside and near each
// subtrahend. The oracle is point membership along the ray (no ray code):
// a distance bound that is too large, or a sign that is wrong, shows the
// minuend's face where the subtrahend should have cut it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <latch>
#include <limits>
#include <random>
#include <thread>
#include <vector>

#include "tests/render/random_csg.hpp"
#include "render/tracer/tracer.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;
using csg::PrimKind;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Whether t is the solid's first entry along o + t·d on (0, 10), by point
// membership alone: outside at every sample before t and just before it,
// inside just after (t = kInf: outside at every sample). Samples are 2.5e-3
// apart, so a slab thinner than that could hide in front of t; the rays here
// cross the minuend face at t > 4 and the cuts are far thicker.
// (k: the scene's scale; lengths along the ray scale with it.)
bool is_first_entry(const csg::Scene& s, const glm::dvec3& o, const glm::dvec3& d, double t, double k = 1) {
    constexpr int kSamples = 4000;
    const double h = 1e-7 * k;
    const double t_end = 10 * k, step = t_end / kSamples;
    for (int i = 1; i <= kSamples && step * i < t - h; ++i)
        if (csg_contains(s, o + step * i * d)) return false;
    if (std::isinf(t)) return true;
    return !csg_contains(s, o + (t - h) * d) && csg_contains(s, o + (t + h) * d);
}

// Rays from above onto random points of the box minuend's top face (z = 1),
// slightly tilted: every answer of intersect() must be the first entry, and
// occluded() must agree with it. Counts rays whose entry is the face itself
// (clear) and rays cut deeper (covered). The scene may be the unit one
// moved to c and scaled by k (world = c + k·local).
void check_rays(const csg::Scene& s, const char* name, std::mt19937_64& rng, int& covered, int& clear, double k = 1,
                glm::dvec3 c = glm::dvec3(0)) {
    std::uniform_real_distribution<double> u(-1, 1);
    const render::CsgTracer tracer(s, false);
    render::TraceScratch scratch;
    for (int i = 0; i < 1500; ++i) {
        const glm::dvec3 target = c + k * glm::dvec3(u(rng), u(rng), 1.0);
        const glm::dvec3 o = target + k * glm::dvec3(0.3 * u(rng), 0.3 * u(rng), 4.0);
        const glm::dvec3 d = glm::normalize(target - o);
        render::TraceHit hit;
        const bool found = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch);
        const double t = found ? hit.t : kInf;
        const double t_face = glm::length(target - o);
        (t > t_face + 1e-6 * k ? covered : clear)++;
        INFO(name << " ray " << i << " first entry " << t << " (the face at " << t_face << ")");
        CHECK(is_first_entry(s, o, d, t, k));
        // Shadow-style query on (0, tfar): blocked exactly when the first
        // entry comes before tfar (the ray starts outside everything).
        const double tfar = t_face + k * (0.05 + 0.5 * (u(rng) + 1));
        if (std::abs(t - tfar) > 1e-6 * k)
            CHECK(tracer.occluded(render::TraceRay{o, d, 0, tfar}, scratch) == (t < tfar));
    }
}

Tree minuend() { return leaf(box({-1, -1, -1}, {1, 1, 1})); }

// Transforms that stretch by up to 3x and shrink by up to 0.4x, so the
// world/object distance conversion is exercised both ways.
const glm::dmat4 twist = rotate_deg(27, glm::normalize(glm::dvec3(1, 2, 0.5)));
const glm::dmat4 near_top = translate(0.1, -0.2, 1.0);

// A groove along the top face: a torus stretched deep, tilted by `deg`.
Tree groove(double x, double deg) {
    return leaf(make_leaf(PrimKind::Torus, {0.8, 0.12},
                          translate(x, 0, 1.0) * rotate_deg(deg, {1, 0, 0}) * scale(1.0, 1.0, 2.5)));
}

// Two overlapping balls breaking through the top face.
Tree lumps() {
    return op(Op::Union, {leaf(sphere(0.3, translate(-0.4, 0.5, 1.1))), leaf(sphere(0.25, translate(-0.1, 0.6, 0.95)))});
}

}  // namespace

TEST_CASE("difference fast path: first entry and occlusion match point membership for every subtrahend kind",
          "[render][difference]") {
    const std::pair<const char*, csg::Leaf> cuts[] = {
        {"sphere", sphere(0.5, near_top * twist * scale(1.8, 0.6, 1.0))},
        {"box", box({-0.5, -0.3, -0.4}, {0.4, 0.5, 0.3}, near_top * twist * scale(0.4, 1.5, 1.0))},
        {"cylinder", make_leaf(PrimKind::Cylinder, {-0.6, 0.6, 0.4, 0.4}, near_top * twist * scale(1.0, 2.0, 1.0))},
        {"cone", make_leaf(PrimKind::Cylinder, {-0.5, 0.7, 0.7, 0.05}, near_top * twist * scale(1.2, 0.8, 3.0))},
        {"torus", make_leaf(PrimKind::Torus, {0.6, 0.3}, near_top * twist * scale(1.5, 1.4, 1.0))},
        {"plane", make_leaf(PrimKind::Plane, {0.3, -0.2, 1.0, 0.8}, twist * scale(1.0, 0.5, 2.0))},
    };
    std::mt19937_64 rng(20261201);
    for (const auto& [name, cut] : cuts) {
        int covered = 0, clear = 0;
        check_rays(make_scene(op(Op::Difference, {minuend(), leaf(cut)})), name, rng, covered, clear);
        // Both outcomes must be common, or the test proves little.
        INFO(name << ": " << covered << " covered, " << clear << " clear");
        CHECK(covered > 100);
        CHECK(clear > 100);
    }
}

TEST_CASE("difference fast path: overlapping and composite subtrahends", "[render][difference]") {
    // Grooves that cross each other (a ray leaving one groove may land in
    // the next), and subtrahends that are unions, intersections and
    // differences themselves.
    const Tree lump = lumps();
    const Tree lens = op(Op::Intersection, {leaf(sphere(0.6, translate(0.5, -0.5, 1.3))),
                                            leaf(sphere(0.6, translate(0.5, -0.5, 0.5)))});
    const Tree ring = op(Op::Difference, {leaf(make_leaf(PrimKind::Cylinder, {0.8, 1.2, 0.5, 0.5})),
                                          leaf(make_leaf(PrimKind::Cylinder, {0.7, 1.3, 0.3, 0.3}))});
    const std::pair<const char*, Tree> sets[] = {
        {"crossing grooves", op(Op::Difference, {minuend(), groove(-0.3, 0), groove(0.3, 90), groove(0, 45)})},
        {"composites", op(Op::Difference, {minuend(), lump, lens, ring})},
        {"grooves and composites", op(Op::Difference, {minuend(), groove(0.2, 30), lump, ring})},
    };
    std::mt19937_64 rng(1201);
    for (const auto& [name, tree] : sets) {
        int covered = 0, clear = 0;
        check_rays(make_scene(tree), name, rng, covered, clear);
        INFO(name << ": " << covered << " covered, " << clear << " clear");
        CHECK(covered > 100);
        CHECK(clear > 100);
    }
}

TEST_CASE("difference fast path: tiny and huge solids away from the origin", "[render][difference]") {
    // The clearance proofs compare squared distances (clearance.cpp) in
    // object space, against the world margin divided by the transform's
    // stretch: the same sphere, box and torus cuts at 1e-3 and 1e4, 100
    // sizes from the origin, so that margin is 1e-3 or 1e4 times the unit
    // scene's and the ray origins are far from the leaves' own origins.
    for (const double k : {1e-3, 1e4}) {
        const glm::dvec3 c(100 * k, -60 * k, 30 * k);
        const glm::dmat4 w = translate(c.x, c.y, c.z) * scale(k, k, k);
        const std::pair<const char*, csg::Leaf> cuts[] = {
            {"sphere", sphere(0.5, w * near_top * twist * scale(1.8, 0.6, 1.0))},
            {"box", box({-0.5, -0.3, -0.4}, {0.4, 0.5, 0.3}, w * near_top * twist * scale(0.4, 1.5, 1.0))},
            {"torus", make_leaf(PrimKind::Torus, {0.6, 0.3}, w * near_top * twist * scale(1.5, 1.4, 1.0))},
        };
        std::mt19937_64 rng(20261205);
        for (const auto& [name, cut] : cuts) {
            int covered = 0, clear = 0;
            const Tree box_minuend = leaf(box({-1, -1, -1}, {1, 1, 1}, w));
            check_rays(make_scene(op(Op::Difference, {box_minuend, leaf(cut)})), name, rng, covered, clear, k, c);
            INFO(name << " at scale " << k << ": " << covered << " covered, " << clear << " clear");
            CHECK(covered > 100);
            CHECK(clear > 100);
        }
    }
}

// Shadow rays that start inside the cuts (a point of a groove, off the
// solid) in every direction: the Any query with one or two subtrahends near
// its probe subtracts only those (difference_fast_path.cpp,
// any_piece_if_clear). occluded() on (0, tfar) must be blocked exactly when
// the first entry, checked by point membership, comes before tfar.
TEST_CASE("difference fast path: shadow rays leaving grooves and lumps", "[render][difference]") {
    const csg::Scene s = make_scene(op(Op::Difference, {minuend(), groove(-0.3, 0), groove(0.3, 90), lumps()}));
    const render::CsgTracer tracer(s, false);
    render::TraceScratch scratch;
    std::mt19937_64 rng(1301);
    std::uniform_real_distribution<double> u(-1, 1);
    int blocked = 0, open = 0;
    for (int i = 0; i < 8000; ++i) {
        const glm::dvec3 o(u(rng), u(rng), 0.8 + 0.2 * u(rng));
        const glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3);
        if (csg_contains(s, o)) continue;
        render::TraceHit hit;
        const double t = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) ? hit.t : kInf;
        INFO("ray " << i << " first entry " << t);
        CHECK(is_first_entry(s, o, d, t));
        const double tfar = 0.05 + 1.5 * (u(rng) + 1);
        if (std::abs(t - tfar) < 1e-6) continue;
        const bool shadow = tracer.occluded(render::TraceRay{o, d, 0, tfar}, scratch);
        CHECK(shadow == (t < tfar));
        (shadow ? blocked : open)++;
    }
    INFO(blocked << " blocked, " << open << " open");
    CHECK(blocked > 800);
    CHECK(open > 300);
}

namespace {

// A box minuend with 6 × 6 round holes through its top, a tilted one
// across two of them and a ball breaking through: more than 8 subtrahends,
// so the difference has its own BVH and subtrahend grid (box_grid.hpp),
// and its first entries and shadows come from the subtrahends the grid
// names near a point (difference_first_entry.cpp).
Tree holed(const glm::dmat4& w) {
    std::vector<Tree> kids{leaf(box({-1, -1, -1}, {1, 1, 1}, w))};
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            kids.push_back(leaf(make_leaf(PrimKind::Cylinder, {0, 3, 0.12, 0.12},
                                          w * translate(-1 + (i + 0.5) / 3, -1 + (j + 0.5) / 3, -1.5))));
    kids.push_back(leaf(make_leaf(PrimKind::Cylinder, {-1.5, 1.5, 0.08, 0.08},
                                  w * translate(0.05, 0.1, 1) * rotate_deg(35, {1, 0.3, 0}))));
    kids.push_back(leaf(sphere(0.2, w * translate(0.5, -0.45, 1.05))));
    return op(Op::Difference, kids);
}

}  // namespace

TEST_CASE("difference with a subtrahend grid: first entries and shadows match point membership", "[render][difference]") {
    for (const double k : {1e-3, 1.0, 1e4}) {
        const glm::dvec3 c(100 * k, -60 * k, 30 * k);
        const csg::Scene s = make_scene(holed(translate(c.x, c.y, c.z) * scale(k, k, k)));
        std::mt19937_64 rng(418);
        int covered = 0, clear = 0;
        check_rays(s, "holes", rng, covered, clear, k, c);
        INFO("scale " << k << ": " << covered << " covered, " << clear << " clear");
        CHECK(covered > 300);
        CHECK(clear > 300);
        // Shadow rays from inside the holes (off the solid), every way: some
        // leave through the opening, some enter the plate or another hole.
        const render::CsgTracer tracer(s, false);
        render::TraceScratch scratch;
        std::uniform_real_distribution<double> u(-1, 1);
        int blocked = 0, open = 0;
        for (int i = 0; i < 3000; ++i) {
            const int hi = int(3 * (u(rng) + 1)), hj = int(3 * (u(rng) + 1));
            const glm::dvec3 local(-1 + (hi + 0.5) / 3 + 0.11 * u(rng), -1 + (hj + 0.5) / 3 + 0.11 * u(rng),
                                   0.5 + 0.5 * u(rng));
            const glm::dvec3 o = c + k * local;
            const glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3);
            if (csg_contains(s, o)) continue;
            render::TraceHit hit;
            const double t = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) ? hit.t : kInf;
            INFO("scale " << k << " shadow ray " << i << " first entry " << t);
            CHECK(is_first_entry(s, o, d, t, k));
            const double tfar = k * (0.02 + 0.8 * (u(rng) + 1));
            if (std::abs(t - tfar) < 1e-6 * k) continue;
            const bool shadow = tracer.occluded(render::TraceRay{o, d, 0, tfar}, scratch);
            CHECK(shadow == (t < tfar));
            (shadow ? blocked : open)++;
        }
        INFO(blocked << " blocked, " << open << " open");
        CHECK(blocked > 500);
        CHECK(open > 300);
    }
}

TEST_CASE("a big difference has its own BVH built by its first query, from two threads at once", "[render][difference]") {
    // The holed box under an intersection with a ball: the intersection asks
    // the difference for all its spans along the ball's chord, which spans
    // more grid cells than the grid answers for, so the gather goes to the
    // difference's BVH, committed only then (build.hpp, Accel::ready). Two
    // threads start on a fresh tracer at once; every first entry must match
    // point membership (an uncommitted BVH finds no subtrahend, and the
    // holes' walls would be missing).
    const csg::Scene s = make_scene(op(Op::Intersection, {holed(glm::dmat4(1)), leaf(sphere(1.3, glm::dmat4(1)))}));
    const render::CsgTracer tracer(s, false);
    struct Ray {
        glm::dvec3 o, d;
        double t;
    };
    std::vector<Ray> rays[2];
    std::latch start(2);
    const auto shoot = [&](int who) {
        std::mt19937_64 rng(77 + who);
        std::uniform_real_distribution<double> u(-1, 1);
        render::TraceScratch scratch;
        start.arrive_and_wait();
        for (int i = 0; i < 1500; ++i) {
            const glm::dvec3 target(u(rng), u(rng), 0.9 * u(rng));
            const glm::dvec3 o = 4.0 * glm::normalize(glm::dvec3(u(rng), u(rng), 0.3 * u(rng)) + 1e-3);
            const glm::dvec3 d = glm::normalize(target - o);
            render::TraceHit hit;
            rays[who].push_back({o, d, tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) ? hit.t : kInf});
        }
    };
    std::thread other(shoot, 1);
    shoot(0);
    other.join();
    int walls = 0;  // entries on a hole's wall or the ball, not the box's faces
    for (int who = 0; who < 2; ++who)
        for (std::size_t i = 0; i < rays[who].size(); ++i) {
            const Ray& r = rays[who][i];
            INFO("thread " << who << " ray " << i << " first entry " << r.t);
            CHECK(is_first_entry(s, r.o, r.d, r.t));
            const glm::dvec3 p = r.o + r.t * r.d;
            if (std::isfinite(r.t) && std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) < 1 - 1e-6) ++walls;
        }
    INFO(walls << " entries inside the box");
    CHECK(walls > 300);
}

// A ray that cuts the minuend's edge over less than the degenerate rule
// meets no solid there: the subtraction drops pieces no longer than eps,
// so the point query's shortcut (c clear of every subtrahend) must too.
// Across the top edge y = z = 1 at x = 0 (between the holes), the chord
// is 2·a·√2 long; a far larger chord is the control.
TEST_CASE("difference with a subtrahend grid: a minuend chord shorter than the degenerate rule is no entry",
          "[render][difference]") {
    const csg::Scene s = make_scene(holed(glm::dmat4(1.0)));
    const glm::dvec3 d = glm::normalize(glm::dvec3(0, 1, -1));
    for (const bool use_float : {false, true}) {
        const render::CsgTracer tracer(s, use_float);
        render::TraceScratch scratch;
        // Far below each path's rule (double: ~2e-9 here; float: ~4e-5).
        const double a_short = use_float ? 1e-7 : 1e-12;
        for (const double a : {a_short, 0.01}) {
            const glm::dvec3 at(0, 1 - a, 1 - a);  // the chord's middle
            const glm::dvec3 o = at - 3.0 * d;
            render::TraceHit hit;
            const bool found = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch);
            INFO((use_float ? "float" : "double") << " path, a = " << a);
            if (a == a_short) {
                CHECK_FALSE(found);
                CHECK_FALSE(tracer.occluded(render::TraceRay{o, d, 0, 6.0}, scratch));
            } else {
                REQUIRE(found);
                CHECK(hit.t == Approx(3.0 - a * std::sqrt(2.0)).margin(1e-6));
            }
        }
    }
}

// Two overlapping holes A and B (x = ∓0.075, r = 0.1) in a plate with a
// grid of small ones. A ray enters the plate's top inside A, δ outside B,
// sloping towards B: it leaves A inside B, and its first entry is B's far
// wall. For δ of a few degenerate rules, B is near the entry point but its
// span starts past the first window (none there), so a later window must
// gather it again; δ runs from far below the rule to far above it.
TEST_CASE("difference with a subtrahend grid: a near subtrahend met only past the first window still cuts",
          "[render][difference]") {
    for (const double k : {1.0, 1e4}) {
        const glm::dvec3 c(100 * k, -60 * k, 30 * k);
        const glm::dmat4 w = translate(c.x, c.y, c.z) * scale(k, k, k);
        std::vector<Tree> kids{leaf(box({-1, -1, -1}, {1, 1, 1}, w))};
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j)
                kids.push_back(leaf(make_leaf(PrimKind::Cylinder, {0, 3, 0.05, 0.05},
                                              w * translate(-1 + (i + 0.5) / 3, -1 + (j + 0.5) / 3, -1.5))));
        for (const double x : {-0.075, 0.075})
            kids.push_back(leaf(make_leaf(PrimKind::Cylinder, {0, 3, 0.1, 0.1}, w * translate(x, 0, -1.5))));
        const csg::Scene s = make_scene(op(Op::Difference, kids));
        const render::CsgTracer tracer(s, false);
        render::TraceScratch scratch;
        const glm::dvec3 d(0.3, 0, -1);
        for (double delta = 1e-14; delta < 1e-5; delta *= std::sqrt(10.0)) {
            const glm::dvec3 entry = c + k * glm::dvec3(-0.025 - delta, 0, 1);
            const glm::dvec3 o = entry - 4 * k * d;
            render::TraceHit hit;
            const double t = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) ? hit.t : kInf;
            INFO("scale " << k << " delta " << delta << " entry " << t);
            CHECK(t == Approx(k * (4 + (0.2 + delta) / 0.3)).epsilon(1e-9));
            CHECK(is_first_entry(s, o, d, t, k));
        }
    }
}

// A half-space minus a few leaves, asked by shadow rays to a directional
// light (tfar = infinity) that run down into it for ever: the minuend's
// part in the window has no middle, so the clearance probe must not be
// taken at infinity (its sliver [inf, inf] has no length, and the unit
// would let the light through the ground). Every ray must be blocked, as
// point membership says (the solid is on the ray just past its start);
// 1 and 3 subtrahends take leaf_minus.cpp's path, 12 the big difference's.
TEST_CASE("shadow rays to infinity through a half-space minus leaves are blocked", "[render][fastpath]") {
    for (const int nsub : {1, 3, 12}) {
        std::vector<Tree> kids{leaf(make_leaf(PrimKind::Plane, {0, 0, 1, 0}))};
        for (int i = 0; i < nsub; ++i) kids.push_back(leaf(sphere(0.5, translate(5 + 2 * i, 5, 0))));
        // (With three, one is a torus near the rays: the far-wall probe of
        // leaf_minus.cpp looks just before the part's end.)
        if (nsub == 3) kids.back() = leaf(make_leaf(PrimKind::Torus, {1, 0.25}, translate(0, 0, 0.1)));
        const csg::Scene s = make_scene(op(Op::Difference, kids));
        const render::CsgTracer tracer(s, false);
        render::TraceScratch scratch;
        int blocked = 0, rays = 0;
        for (double x = -2; x <= 2; x += 0.5)
            for (double y = -2; y <= 2; y += 0.5) {
                const glm::dvec3 o(x, y, 0.5), d(-0.3, -0.2, -1);
                INFO(nsub << " subtrahends, from " << x << ", " << y);
                REQUIRE(csg_contains(s, o + 1.0 * d));
                ++rays;
                blocked += tracer.occluded(render::TraceRay{o, d, 1e-6, kInf}, scratch);
            }
        CHECK(blocked == rays);
    }
}

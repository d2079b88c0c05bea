// Nodes of analytic leaves evaluated in one step (render/tracer/
// node_spans.cpp, leaf_pair_spans: a union, intersection or difference of
// two leaves; leaf_minus.cpp: a leaf minus a few leaves asked for its first
// entry or any span). Their spans never touch the span stack until the
// answer, so these tests put each shape where the tracer asks it every
// question: as a unit (first entry, shadows), as the minuend of a difference
// and under an intersection (every span), as a subtrahend (every span on a
// window). The oracle is point membership along the ray (csg::contains),
// never a tracer answer; scenes are scaled to 1e-3 and 1e4 and moved away
// from the origin, rays graze spheres, and faces coincide.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "tests/render/random_csg.hpp"
#include "render/tracer/tracer.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;
using csg::PrimKind;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kGraze = 1.2;  // the local radius the grazing rays touch

// World placement: world = at + k·local.
struct Place {
    double k = 1;
    glm::dvec3 at{0.0};
    glm::dmat4 m() const { return translate(at.x, at.y, at.z) * scale(k, k, k); }
    glm::dvec3 operator()(const glm::dvec3& local) const { return at + k * local; }
};

// Whether t is the first entry of the solid along o + t·d in (0, t_end) by
// membership alone: outside at every one of n samples before t - h, outside
// at t - h and inside at t + h (t = kInf: outside at every sample).
bool membership_first_entry(const csg::Scene& s, const glm::dvec3& o, const glm::dvec3& d, double t, double t_end,
                            double h) {
    constexpr int n = 3000;
    for (int i = 1; i <= n; ++i) {
        const double ti = t_end * i / n;
        if (ti >= t - h) break;
        if (csg_contains(s, o + ti * d)) return false;
    }
    if (std::isinf(t)) return true;
    return !csg_contains(s, o + (t - h) * d) && csg_contains(s, o + (t + h) * d);
}

struct Counts {
    int hits = 0, misses = 0, blocked = 0, open = 0;
};

// Rays from outside the local ball of radius 3 (origin within 6) at random
// points of the local cube of half-side 0.8, a quarter grazing the sphere of
// radius `graze` (tangent to it at a random point, 1e-9 off either side): intersect() must
// give the membership first entry, and occluded() on (0, tfar) must be
// blocked exactly when that entry is before tfar.
void check_rays(const csg::Scene& s, const Place& p, std::uint64_t seed, Counts& c, int rays, double graze = kGraze) {
    const render::CsgTracer tracer(s, false);
    render::TraceScratch scratch;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto unit = [&] { return glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3); };
    for (int i = 0; i < rays; ++i) {
        glm::dvec3 from, to;
        if (i % 4 == 0) {
            const glm::dvec3 n = unit(), side = glm::normalize(glm::cross(n, unit()));
            to = graze * (1 + 1e-9 * u(rng)) * n;
            from = to - 5.0 * side;
        } else {
            from = 5.0 * unit();
            to = 0.8 * glm::dvec3(u(rng), u(rng), u(rng));
        }
        const glm::dvec3 o = p(from), d = glm::normalize(p(to) - o);
        if (csg_contains(s, o)) continue;
        render::TraceHit hit;
        const double t = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) ? hit.t : kInf;
        INFO("ray " << i << " from " << from.x << "," << from.y << "," << from.z << " first entry " << t / p.k);
        CHECK(membership_first_entry(s, o, d, t, 10 * p.k, 1e-7 * p.k));
        (std::isinf(t) ? c.misses : c.hits)++;
        const double tfar = p.k * (5 + 3 * u(rng));
        if (std::abs(t - tfar) < 1e-6 * p.k) continue;
        const bool shadow = tracer.occluded(render::TraceRay{o, d, 0, tfar}, scratch);
        CHECK(shadow == (t < tfar));
        (shadow ? c.blocked : c.open)++;
    }
}

// Two random analytic leaves (no half-spaces: the rays' samples stop at
// 10), every fourth time the first a ball of radius kGraze that the grazing
// rays touch.
Tree pair(RandomCsg& gen, Op o, bool ball) {
    const Tree first = leaf(gen.primitive(0, false));
    return op(o, {ball ? leaf(sphere(kGraze)) : first, leaf(gen.primitive(1, false))});
}

// The tree scaled by k and moved to `at` (leaves only; no planes here).
Tree placed(Tree t, const Place& p) {
    if (t.op != Op::Leaf) {
        for (Tree& k : t.kids) k = placed(std::move(k), p);
        return t;
    }
    const csg::Leaf& l = t.leaf;
    glm::dmat4 w(l.world_from_object.linear);
    w[3] = glm::dvec4(l.world_from_object.offset, 1.0);
    t.leaf = make_leaf(l.kind, std::vector<double>(l.p, l.p + 6), p.m() * w, l.material);
    return t;
}

// The operands of bench/scenes.py's grooved sphere (a ball minus six tori)
// and fishbowl (a ball minus a smaller ball and a cone from its centre up
// through the top), the minuend first.
std::vector<Tree> grooved_ball() {
    std::vector<Tree> kids = {leaf(sphere(1))};
    const glm::dmat4 rots[3] = {glm::dmat4(1.0), rotate_deg(90, {0, 1, 0}), rotate_deg(90, {1, 0, 0})};
    for (const glm::dmat4& r : rots)
        for (const double flip : {0.0, 180.0})
            kids.push_back(leaf(make_leaf(PrimKind::Torus, {1, 0.1},
                                          r * rotate_deg(flip, {0, 1, 0}) * translate(0, 0, 0.374) * scale(0.9, 0.9, 0.9))));
    return kids;
}
std::vector<Tree> fishbowl_kids() {
    return {leaf(sphere(1)), leaf(sphere(0.9)),
            leaf(make_leaf(PrimKind::Cylinder, {0, 1.2, 0.6, 0}, translate(0, 0, 1.2) * scale(1, 1, -1)))};
}

const Place kPlaces[] = {{1, {0, 0, 0}}, {1, {1e3, -2e3, 5e2}}, {1e-3, {3e-3, -2e-3, 5e-3}}, {1e4, {-4e5, 2e5, 1e5}}};

}  // namespace

TEST_CASE("leaf pairs: unions, intersections and differences of two leaves match point membership",
          "[render][tracer][leaf]") {
    // Each pair as a unit, as a difference's minuend (its every span), under
    // an intersection and as a subtrahend (every span on a window).
    for (const Place& p : kPlaces) {
        Counts c;
        for (std::uint64_t seed = 1; seed <= 24; ++seed) {
            RandomCsg gen(seed * 7919);
            const Op ops[3] = {Op::Union, Op::Intersection, Op::Difference};
            const Tree two = pair(gen, ops[seed % 3], seed % 4 == 0);
            const Tree other = leaf(gen.primitive(2, false));
            const Tree shapes[] = {two, op(Op::Difference, {two, other}), op(Op::Intersection, {other, two}),
                                   op(Op::Difference, {other, two})};
            const Tree& tree = shapes[(seed / 3) % 4];
            INFO("scale " << p.k << " seed " << seed << " op " << int(ops[seed % 3]) << " shape " << (seed / 3) % 4);
            check_rays(make_scene(placed(tree, p)), p, seed, c, 150);
        }
        INFO("scale " << p.k << ": " << c.hits << " hits, " << c.misses << " misses, " << c.blocked << " blocked");
        CHECK(c.hits > 600);
        CHECK(c.misses > 300);
        CHECK(c.blocked > 300);
        CHECK(c.open > 300);
    }
}

TEST_CASE("leaf pairs and leaf minus leaves: coincident faces leave no slivers", "[render][tracer][leaf]") {
    // A − A is empty; a box minus a box flush with its top face, the union of
    // two boxes sharing a face and the intersection of a sphere with itself
    // are their regularised sets (no sliver, no inner surface), whatever the
    // scale and place.
    for (const Place& p : kPlaces) {
        const csg::Leaf b = box({-1, -1, -1}, {1, 1, 1}, glm::dmat4(1.0));
        const csg::Leaf top = box({-0.5, -0.5, 0}, {0.5, 0.5, 1}, glm::dmat4(1.0));
        const csg::Leaf right = box({1, -1, -1}, {2, 1, 1}, glm::dmat4(1.0));
        const csg::Leaf ball = sphere(kGraze);
        const Tree trees[] = {
            op(Op::Difference, {leaf(ball), leaf(ball)}),
            op(Op::Difference, {leaf(b), leaf(top)}),
            op(Op::Difference, {leaf(b), leaf(top), leaf(right), leaf(sphere(0.3, translate(-1, -1, 1)))}),
            op(Op::Union, {leaf(b), leaf(right)}),
            op(Op::Intersection, {leaf(ball), leaf(ball)}),
            op(Op::Difference, {op(Op::Union, {leaf(b), leaf(right)}), leaf(top)}),
        };
        Counts c;
        std::uint64_t seed = 40;
        for (const Tree& t : trees) {
            INFO("scale " << p.k << " tree " << seed - 40);
            check_rays(make_scene(placed(t, p)), p, seed++, c, 300);
        }
        INFO("scale " << p.k << ": " << c.hits << " hits, " << c.misses << " misses");
        CHECK(c.hits > 600);
        CHECK(c.misses > 300);
    }
}

namespace {

// Shadow rays leaving the cuts of `s`, checked against the membership first
// entry: from random points of the cuts (in the cube of half-side `ball`,
// inside the minuend, off the solid) and from the cut faces as the shader
// leaves them (100 degenerate rules off along the normal), in random
// directions (on the normal's side). Returns {blocked, open}.
template <typename InMinuend>
std::pair<int, int> check_cut_shadows(const csg::Scene& s, const Place& p, double ball, InMinuend in_minuend,
                                      std::uint64_t seed) {
    const render::CsgTracer tracer(s, false);
    render::TraceScratch scratch;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const auto unit = [&] { return glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3); };
    int blocked = 0, open = 0;
    // `from`: the surface the ray leaves, as the shader hands it over (a cut
    // face's Departure: shadow_rays.cpp, "Hollow").
    const auto check = [&](const glm::dvec3& o, const glm::dvec3& d, const char* what, int i,
                           const render::Departure* from = nullptr) {
        render::TraceHit hit;
        const double t = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) ? hit.t : kInf;
        INFO("scale " << p.k << " " << what << " " << i << " first entry " << t / p.k);
        CHECK(membership_first_entry(s, o, d, t, 3 * p.k, 1e-7 * p.k));
        const double tfar = p.k * (0.02 + (u(rng) + 1));
        if (std::abs(t - tfar) < 1e-6 * p.k) return;
        const bool shadow = tracer.occluded(render::TraceRay{o, d, 0, tfar}, scratch, from);
        CHECK(shadow == (t < tfar));
        (shadow ? blocked : open)++;
    };
    for (int i = 0, n = 0; i < 20000 && n < 1500; ++i) {
        const glm::dvec3 local = ball * glm::dvec3(u(rng), u(rng), u(rng));
        if (!in_minuend(local) || csg_contains(s, p(local))) continue;
        ++n;
        check(p(local), unit(), "ray from a cut", i);
    }
    for (int i = 0, n = 0; i < 20000 && n < 1500; ++i) {
        // A camera ray onto the solid; its hit on a cut face (flipped).
        const glm::dvec3 o = p(5.0 * unit()), d = glm::normalize(p(0.8 * ball * unit()) - o);
        render::TraceHit hit;
        if (!tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) || !hit.surface.flip) continue;
        const glm::dvec3 x = o + hit.t * d, n_out = tracer.normal(hit, x);
        const glm::dvec3 from = x + tracer.surface_offset(hit, x) * n_out;
        glm::dvec3 dir = unit();
        if (glm::dot(dir, n_out) < 0) dir = -dir;
        // Every fourth ray nearly along the face (within 1e-3 of it).
        if (i % 4 == 0) dir = glm::normalize(dir - glm::dot(dir, n_out) * n_out + 1e-3 * (u(rng) + 1) * n_out);
        ++n;
        const render::Departure leaving = tracer.departure(hit, n_out);
        check(from, dir, "ray from a cut face", i, &leaving);
    }
    return {blocked, open};
}

}  // namespace

TEST_CASE("leaf minus leaves: shadow rays leaving grooves and pockets match point membership",
          "[render][tracer][leaf]") {
    // The grooved sphere of bench/scenes.py (a sphere minus six tori), and
    // a box with a spherical dimple, a box pocket and a torus groove, at
    // four scales and places: rays from outside, then shadow rays leaving
    // the cuts, many through their openings, which a near torus, ball or box
    // holding the whole segment answers without a solve (leaf_minus.cpp,
    // segment_inside), many into a groove's far wall, which a second probe
    // just before the minuend's exit answers when it is clear of every
    // subtrahend (fails when that probe skips the near tori: 2,436 checks,
    // or lies past the exit: 264).
    for (const Place& p : kPlaces) {
        const std::vector<Tree> kids = grooved_ball();
        const Tree pocketed = op(Op::Difference, {leaf(box({-0.7, -0.7, -0.7}, {0.7, 0.7, 0.7})),
                                                  leaf(sphere(0.35, translate(0.3, 0.3, 0.75))),
                                                  leaf(box({-0.5, -0.5, 0.3}, {-0.1, 0.2, 1}, rotate_deg(10, {0, 0, 1}))),
                                                  leaf(make_leaf(PrimKind::Torus, {0.5, 0.12},
                                                                 rotate_deg(90, {1, 0, 0}) * translate(0, 0.0, -0.7)))});
        for (const bool ball : {true, false}) {
            const char* name = ball ? "grooved ball" : "pocketed box";
            const csg::Scene s = make_scene(placed(ball ? op(Op::Difference, kids) : pocketed, p));
            Counts c;
            check_rays(s, p, 77, c, 600, 1.0);
            INFO(name << " at scale " << p.k << ": " << c.hits << " hits");
            CHECK(c.hits > 200);
            const auto in_minuend = [ball](const glm::dvec3& q) {
                return ball ? glm::length(q) < 1 : std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)}) < 0.7;
            };
            const auto [blocked, open] = check_cut_shadows(s, p, 1.0, in_minuend, 78);
            INFO(name << " at scale " << p.k << ": " << blocked << " blocked, " << open << " open");
            CHECK(blocked > 500);
            CHECK(open > 500);
        }
    }
}

TEST_CASE("leaf minus leaves: the fishbowl's opening, near spans reused, matches point membership",
          "[render][tracer][leaf]") {
    // The fishbowl of bench/scenes.py (a ball minus a smaller ball and a
    // cone from its centre up through the top), and the same with a slot
    // (a box) through its wall. A ray into the opening enters the minuend
    // inside the cone: the fast path intersects the cone alone, finds the
    // piece behind it inside the inner ball and gives up; the full
    // subtraction on the same window then takes the cone's spans from the
    // fast path (leaf_minus.cpp, NearSpans) and intersects only the rest.
    // Shadow rays leaving the inner wall likewise. Both at four scales.
    for (const Place& p : kPlaces) {
        for (const bool slot : {false, true}) {
            std::vector<Tree> kids = fishbowl_kids();
            if (slot) kids.push_back(leaf(box({-0.15, -1.2, -0.5}, {0.15, 0, 0.2}, rotate_deg(20, {0, 0, 1}))));
            const csg::Scene s = make_scene(placed(op(Op::Difference, kids), p));
            Counts c;
            check_rays(s, p, 91, c, 800, 1.0);
            INFO((slot ? "slotted " : "") << "fishbowl at scale " << p.k << ": " << c.hits << " hits");
            CHECK(c.hits > 300);
            const auto in_minuend = [](const glm::dvec3& q) { return glm::length(q) < 1; };
            const auto [blocked, open] = check_cut_shadows(s, p, 1.0, in_minuend, 92);
            INFO((slot ? "slotted " : "") << "fishbowl at scale " << p.k << ": " << blocked << " blocked, " << open
                                          << " open");
            CHECK(blocked > 500);
            CHECK(open > 300);
        }
    }
}

TEST_CASE("solve_ahead: camera rays with their sphere solved ahead hit what they hit without, to the bit",
          "[render][tracer][leaf]") {
    // CsgTracer::solve_ahead (tracer.hpp): the grooved ball and the fishbowl
    // at four scales and places, rows of 8 rays from outside (a quarter
    // grazing the ball). Each ray's first entry with its row's spans handed
    // over (TraceScratch::ahead) must be the one without, bit for bit, and
    // the membership first entry; handed its neighbour's, the query must
    // solve its own (fails without the ray check in analytic_spans); handed
    // its own with the entry moved, it must take them (the hand-over is
    // used at all). A box minuend and the float tracer solve nothing ahead.
    for (const Place& p : kPlaces) {
        const std::vector<Tree> grooved = grooved_ball(), fishbowl = fishbowl_kids();
        for (const bool bowl : {false, true}) {
            const csg::Scene s = make_scene(placed(op(Op::Difference, bowl ? fishbowl : grooved), p));
            const render::CsgTracer tracer(s, false);
            render::TraceScratch scratch;
            std::mt19937_64 rng(bowl ? 12 : 11);
            std::uniform_real_distribution<double> u(-1, 1);
            const auto unit = [&] { return glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3); };
            int hits = 0, moved = 0;
            for (int row = 0; row < 60; ++row) {
                render::TraceRay rays[8];
                for (render::TraceRay& ray : rays) {
                    glm::dvec3 from, to;
                    if (rng() % 4 == 0) {
                        const glm::dvec3 n = unit(), side = glm::normalize(glm::cross(n, unit()));
                        to = (1 + 1e-9 * u(rng)) * n;
                        from = to - 5.0 * side;
                    } else {
                        from = 5.0 * unit();
                        to = 0.8 * glm::dvec3(u(rng), u(rng), u(rng));
                    }
                    ray = {p(from), glm::normalize(p(to) - p(from)), 0, kInf};
                }
                render::AheadSpans ahead[8];
                REQUIRE(tracer.solve_ahead(rays, 8, ahead));
                for (int i = 0; i < 8; ++i) {
                    const render::TraceRay& ray = rays[i];
                    if (csg_contains(s, ray.o)) continue;
                    render::TraceHit h0, h1, h2, h3;
                    const bool a0 = tracer.intersect(ray, h0, scratch);
                    scratch.ahead = &ahead[i];
                    const bool a1 = tracer.intersect(ray, h1, scratch);
                    scratch.ahead = &ahead[(i + 1) % 8];
                    const bool a2 = tracer.intersect(ray, h2, scratch);
                    render::AheadSpans wrong = ahead[i];
                    if (wrong.count > 0) wrong.spans[0].t0 += 0.05 * p.k;
                    scratch.ahead = &wrong;
                    const bool a3 = tracer.intersect(ray, h3, scratch);
                    // The same moved spans named as another leaf's: refused too.
                    render::AheadSpans other = wrong;
                    other.leaf += 1;
                    scratch.ahead = &other;
                    render::TraceHit h4;
                    const bool a4 = tracer.intersect(ray, h4, scratch);
                    scratch.ahead = nullptr;
                    INFO((bowl ? "fishbowl" : "grooved ball") << " at scale " << p.k << ", row " << row << " ray " << i);
                    CHECK(a1 == a0);
                    CHECK(a2 == a0);
                    CHECK(a4 == a0);
                    if (a0 && a1 && a2 && a4) {
                        CHECK(h1.t == h0.t);
                        CHECK(h2.t == h0.t);
                        CHECK(h4.t == h0.t);
                        CHECK(h1.surface.leaf == h0.surface.leaf);
                        CHECK(h1.surface.part == h0.surface.part);
                        ++hits;
                        moved += !a3 || h3.t != h0.t;
                    }
                    CHECK(membership_first_entry(s, ray.o, ray.d, a1 ? h1.t : kInf, 10 * p.k, 1e-7 * p.k));
                }
            }
            INFO((bowl ? "fishbowl" : "grooved ball") << " at scale " << p.k << ": " << hits << " hits, " << moved
                                                      << " moved by the wrong spans");
            CHECK(hits > 150);
            CHECK(moved > 50);
            render::AheadSpans unused[1];
            CHECK_FALSE(render::CsgTracer(s, true).solve_ahead(nullptr, 0, unused));
        }
        const csg::Scene boxed = make_scene(placed(
            op(Op::Difference, {leaf(box({-0.7, -0.7, -0.7}, {0.7, 0.7, 0.7})), leaf(sphere(0.35, translate(0.3, 0.3, 0.75)))}),
            p));
        render::AheadSpans unused[1];
        CHECK_FALSE(render::CsgTracer(boxed, false).solve_ahead(nullptr, 0, unused));
    }
}

// A big crowd's tracer build runs some steps on one thread of the arena
// while the others build the rest (render/tracer/parallel_build.hpp,
// ConcurrentStep): the shadow rays' per-leaf tables, the root union's BVH
// items (copied to the top level's), TowardLight's radii beside the sphere
// grid. A lattice of 35,937 spheres (past kParallelBuild) directly under
// the root, the same under two nested unions (the units found through
// them), and directly under the root beside a union child holding its last
// sphere, or beside an empty union (the root's items split out beside the
// tables, but not the top level's to copy), built in arenas of 1 and 2
// threads: every camera ray's entry
// against the closed form (the nearest sphere entry along it), the same
// entry and leaf on both, and every departing shadow ray's answer against
// the closed form too. Every fifth camera ray is aimed at the first or
// last sphere of the list or of a half.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <tbb/task_arena.h>

#include "render/tracer/parallel_build.hpp"
#include "render/tracer/tracer.hpp"
#include "tests/render/grazing_rays.hpp"
#include "tests/render/random_csg.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;
using render::ConcurrentStep;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The first t in (tmin, tmax) where o + t d enters one of the balls (o
// outside them all), and the ball's gap: how far the ray passes inside its
// rim (tiny: grazing, no answer asked).
double first_entry(const std::vector<Ball>& balls, const glm::dvec3& o, const glm::dvec3& d, double tmax,
                   double* gap = nullptr) {
    double best = kInf, best_gap = kInf;
    for (const Ball& b : balls) {
        const glm::dvec3 w = b.c - o;
        const double tc = glm::dot(w, d), q2 = glm::dot(w, w) - tc * tc, h2 = b.r * b.r - q2;
        if (!(h2 > 0)) continue;
        const double t = tc - std::sqrt(h2);
        if (t > 0 && t < tmax && t < best) {
            best = t;
            best_gap = b.r - std::sqrt(std::max(q2, 0.0));
        }
    }
    if (gap) *gap = best_gap;
    return best;
}

enum class Shape { Flat, Nested, UnionChild, EmptyUnion };

void check_crowd(Shape shape) {
    const bool nested = shape == Shape::Nested;
    const int m = 33;
    const double p = 2.0 / m;
    std::vector<Ball> balls;
    std::vector<Tree> kids;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int l = 0; l < m; ++l) {
                balls.push_back({p * glm::dvec3(i + 0.5 - 0.5 * m, j + 0.5 - 0.5 * m, l + 0.5 - 0.5 * m), 0.35 * p});
                kids.push_back(leaf(sphere(balls.back().r, translate(balls.back().c.x, balls.back().c.y, balls.back().c.z))));
            }
    Tree tree = op(Op::Union, {});
    if (nested) {
        const std::size_t half = kids.size() / 2;
        tree.kids.push_back(op(Op::Union, std::vector<Tree>(kids.begin(), kids.begin() + std::ptrdiff_t(half))));
        tree.kids.push_back(op(Op::Union, std::vector<Tree>(kids.begin() + std::ptrdiff_t(half), kids.end())));
    } else if (shape == Shape::UnionChild) {
        tree.kids.assign(kids.begin(), kids.end() - 1);
        tree.kids.push_back(op(Op::Union, {kids.back()}));
    } else {
        tree.kids = kids;
        if (shape == Shape::EmptyUnion) tree.kids.push_back(op(Op::Union, {}));
    }
    csg::Scene s = make_scene(tree);
    s.camera.position = glm::dvec3(3, -8, 4);
    s.camera.look_at = glm::dvec3(0.0);
    s.lights.clear();
    s.lights.push_back(csg::Light{false, glm::dvec3(-5, -7, 10), {0, 0, -1}, {1, 1, 1}, 1});
    std::optional<render::CsgTracer> one, two;
    tbb::task_arena(1).execute([&] { one.emplace(s, false); });
    tbb::task_arena(2).execute([&] { two.emplace(s, false); });
    RandomCsg g(70 + int(shape));
    render::TraceScratch kept, fresh;
    int hits = 0, lit = 0, shadowed = 0;
    for (int i = 0; i < 300; ++i) {
        const glm::dvec3 u = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
        const glm::dvec3 from = 3.0 * u;
        // Every fifth at the first or last sphere of the list or of a half
        // (where a unit list's start or end would be lost), else any.
        const std::size_t n = balls.size(), ends[4] = {0, n / 2 - 1, n / 2, n - 1};
        const Ball& target = balls[i % 5 == 0 ? ends[(i / 5) % 4] : std::size_t(g.pick(int(n)))];
        const glm::dvec3 d = aim(g, from, target, 0.5, false);
        double gap = 0;
        const double t_true = first_entry(balls, from, d, kInf, &gap);
        render::TraceHit h1, h2;
        const bool hit1 = one->intersect(render::TraceRay{from, d, 0, kInf}, h1, fresh);
        const bool hit2 = two->intersect(render::TraceRay{from, d, 0, kInf}, h2, fresh);
        INFO("shape " << int(shape) << " ray " << i << " closed form " << t_true);
        REQUIRE(hit1 == hit2);
        if (hit1) {
            CHECK(h1.t == h2.t);
            CHECK(h1.surface.leaf == h2.surface.leaf);
        }
        if (gap < 1e-9) continue;  // (grazing: either answer is right)
        REQUIRE(hit1 == std::isfinite(t_true));
        if (!hit1) continue;
        ++hits;
        CHECK(std::abs(h1.t - t_true) <= 1e-9 * (1 + t_true));
        // The shadow ray the shader would send from there (departure tables).
        const glm::dvec3 q = from + h1.t * d;
        const glm::dvec3 nrm = one->normal(h1, q);
        const glm::dvec3 o = q + one->surface_offset(h1, q) * nrm;
        const glm::dvec3 light = s.lights[0].position;
        const double dist = glm::length(light - o);
        const glm::dvec3 l = (light - o) / dist;
        if (!(glm::dot(nrm, l) > 0)) continue;
        double sgap = 0;
        const double te = first_entry(balls, o, l, dist, &sgap);
        if (std::isfinite(te) && sgap < 1e-9) continue;
        for (const render::CsgTracer* t : {&*one, &*two}) {
            const render::Departure dep = t->departure(h1, nrm);
            CHECK(t->occluded(render::TraceRay{o, l, 0, dist}, kept, &dep) == std::isfinite(te));
        }
        (std::isfinite(te) ? shadowed : lit)++;
    }
    CHECK(hits > 100);
    CHECK(lit > 10);
    CHECK(shadowed > 10);
}

}  // namespace

TEST_CASE("a big crowd's tracer built with concurrent steps: entries and shadows by closed form, the same on 1 "
          "and 2 threads",
          "[render][oracle]") {
    check_crowd(Shape::Flat);
    check_crowd(Shape::Nested);
    check_crowd(Shape::UnionChild);
    check_crowd(Shape::EmptyUnion);
}

TEST_CASE("ConcurrentStep: the step has run when join returns, and join rethrows its exception", "[render]") {
    tbb::task_arena(2).execute([] {
        for (const bool concurrent : {false, true}) {
            std::vector<int> done(100000, 0);
            ConcurrentStep step(concurrent, [&] {
                for (int& x : done) x = 1;
            });
            step.join();
            int sum = 0;
            for (int x : done) sum += x;
            CHECK(sum == 100000);
            const auto fail = [] { throw std::runtime_error("step failed"); };
            if (concurrent) {
                ConcurrentStep failing(true, fail);
                CHECK_THROWS_WITH(failing.join(), "step failed");
            } else {
                CHECK_THROWS_WITH(ConcurrentStep(false, fail), "step failed");  // run at once
            }
        }
    });
}

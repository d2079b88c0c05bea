// A shadow ray that leaves a convex leaf holding its whole unit (a sphere
// minus something, an intersection with a box, a plain cylinder) skips that
// unit (render/tracer/tracer.hpp, Departure). Here a crowd of such units,
// under rotations, non-uniform scales and mirrors, is hit by camera rays;
// from each hit, rays leave the surface as the shader sends them (from the
// surface offset along the outward normal) in random directions of the
// outer hemisphere, grazing ones included. Every answer with the departure
// must equal the full evaluation's, and point membership along the ray (no
// ray code) must find no point inside the left leaf: a leaf wrongly taken
// for convex, or for holding its unit, shows as a lost shadow.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "csg/membership.hpp"
#include "render/tracer/tracer.hpp"
#include "tests/render/random_csg.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;
using csg::PrimKind;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// 30 overlapping units: sphere minus a sphere or a box, box ∩ sphere,
// sphere ∩ cylinder, a plain box, a torus minus a sphere (not convex: never
// skipped), and one union of two spheres (its operands hold only a part).
Tree crowd(RandomCsg& g) {
    Tree t = op(Op::Union, {});
    for (int k = 0; k < 30; ++k) {
        const glm::dvec3 axis = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
        glm::dvec3 s(g.uni(0.4, 1.2), g.uni(0.4, 1.2), g.uni(0.4, 1.2));
        if (g.pick(5) == 0) s.x = -s.x;
        const glm::dmat4 m = translate(g.uni(-2, 2), g.uni(-2, 2), g.uni(-2, 2)) * rotate_deg(g.uni(0, 360), axis) *
                             scale(s.x, s.y, s.z);
        const double r = g.uni(0.3, 0.6);
        const csg::Leaf ball = sphere(r, m);
        switch (g.pick(7)) {
            case 0: t.kids.push_back(op(Op::Difference, {leaf(ball), leaf(sphere(0.8 * r, m * translate(0.3 * r, 0, 0)))})); break;
            case 1: t.kids.push_back(op(Op::Difference, {leaf(ball), leaf(box(glm::dvec3(0.0), glm::dvec3(r), m))})); break;
            case 2: t.kids.push_back(op(Op::Intersection, {leaf(box(glm::dvec3(-0.7 * r), glm::dvec3(0.7 * r), m)), leaf(ball)})); break;
            case 3:
                t.kids.push_back(op(Op::Intersection, {leaf(ball), leaf(make_leaf(PrimKind::Cylinder, {-r, r, 0.6 * r, 0.3 * r}, m))}));
                break;
            case 4: t.kids.push_back(leaf(box(glm::dvec3(-r), glm::dvec3(r), m))); break;
            case 5:
                t.kids.push_back(op(Op::Difference, {leaf(make_leaf(PrimKind::Torus, {r, 0.4 * r}, m)), leaf(sphere(0.5 * r, m))}));
                break;
            default: t.kids.push_back(op(Op::Union, {leaf(ball), leaf(sphere(r, m * translate(0.8 * r, 0, 0)))})); break;
        }
    }
    return t;
}

}  // namespace

TEST_CASE("departure: shadow rays leaving a convex leaf that holds its unit skip only what cannot block",
          "[render][oracle]") {
    // Double and float intersections (--precision float rounds its hits at
    // ~1e-7: the surface offset must still put the ray in front of the leaf).
    const bool use_float = GENERATE(false, true);
    int skipped = 0, blocked = 0;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        RandomCsg g(seed);
        const csg::Scene s = make_scene(crowd(g));
        const render::CsgTracer tracer(s, use_float);
        render::TraceScratch scratch;
        for (int i = 0; i < 600; ++i) {
            const glm::dvec3 u = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
            const glm::dvec3 o = 9.0 * u;
            const glm::dvec3 d = glm::dvec3(g.uni(-2, 2), g.uni(-2, 2), g.uni(-2, 2)) - o;
            render::TraceHit hit;
            if (!tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch)) continue;
            const glm::dvec3 p = o + hit.t * d;
            const glm::dvec3 n = tracer.normal(hit, p);
            if (glm::dot(n, d) > 0) continue;  // the shader turns n: no departure there
            const render::Departure from = tracer.departure(hit, n);
            const glm::dvec3 origin = p + tracer.surface_offset(hit, p) * n;
            for (int j = 0; j < 8; ++j) {
                // Random outward directions, every other one grazing the
                // tangent plane (cosines down to 1e-9, below the cut-off).
                glm::dvec3 l = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
                if (glm::dot(l, n) < 0) l = -l;
                if (j % 2 == 1) l = glm::normalize(l - glm::dot(l, n) * n + std::pow(10.0, -g.uni(1, 9)) * n);
                const double tfar = g.uni(0.5, 12);
                const render::TraceRay ray{origin, l, 0, tfar};
                const bool full = tracer.occluded(ray, scratch);
                INFO("float " << use_float << " seed " << seed << " ray " << i << " shadow " << j);
                CHECK(tracer.occluded(ray, scratch, &from) == full);
                blocked += full ? 1 : 0;
                if (from.unit == csg::kNone) continue;
                ++skipped;
                const csg::Leaf& left = s.leaves[hit.surface.leaf];
                bool inside = false;
                for (int k = 1; k <= 400 && !inside; ++k)
                    inside = csg::contains(left, left.object_from_world.point(origin + (tfar * k / 400) * l));
                CHECK_FALSE(inside);
            }
        }
    }
    CHECK(skipped > 2000);  // the departure is taken (the test exercises it)
    CHECK(blocked > 500);   // and the other units still cast shadows
}

namespace {

// Units far apart (no two overlap): a plate minus a 5 × 5 grid of
// cylinders, a tilted cylinder, a ball and a box (a big difference: its own
// BVH and grid); a ball minus two crossing cylinders (a small difference);
// a block with a hole and a ball in that hole, under a union inside an
// intersection (the union's operands hold only a part of the unit: the
// ball is inside the hole's cylinder, so its inside is not empty of it).
// `alone`: the plate only, a one-unit scene (occluded's first test).
Tree hollows(const glm::dmat4& w, bool alone = false) {
    std::vector<Tree> plate{leaf(box({-1, -1, -1}, {1, 1, 1}, w))};
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            plate.push_back(leaf(make_leaf(PrimKind::Cylinder, {0, 3, 0.15, 0.15},
                                           w * translate(-1 + (i + 0.5) * 0.4, -1 + (j + 0.5) * 0.4, -1.5))));
    plate.push_back(leaf(make_leaf(PrimKind::Cylinder, {-1.5, 1.5, 0.1, 0.1}, w * translate(0.05, 0.1, 1) * rotate_deg(35, {1, 0.3, 0}))));
    plate.push_back(leaf(sphere(0.25, w * translate(0.5, -0.45, 1.05))));
    plate.push_back(leaf(box({-0.3, -0.3, -0.3}, {0.3, 0.3, 0.3}, w * translate(-1, 1, 0) * rotate_deg(30, {0, 0, 1}))));
    if (alone) return op(Op::Difference, plate);
    const glm::dmat4 w2 = w * translate(4, 0, 0);
    Tree ball = op(Op::Difference, {leaf(sphere(1, w2)), leaf(make_leaf(PrimKind::Cylinder, {-2, 2, 0.4, 0.4}, w2)),
                                    leaf(make_leaf(PrimKind::Cylinder, {-2, 2, 0.3, 0.3}, w2 * rotate_deg(90, {1, 0, 0})))});
    const glm::dmat4 w3 = w * translate(0, 4, 0);
    Tree block = op(Op::Intersection,
                    {leaf(box({-1.5, -1.5, -1.5}, {1.5, 1.5, 1.5}, w3)),
                     op(Op::Union, {op(Op::Difference, {leaf(box({-1, -1, -1}, {1, 1, 1}, w3)),
                                                        leaf(make_leaf(PrimKind::Cylinder, {-2, 2, 0.6, 0.6}, w3))}),
                                    leaf(sphere(0.3, w3 * translate(0, 0, 0.2)))})});
    return op(Op::Union, {op(Op::Difference, plate), ball, block});
}

}  // namespace

TEST_CASE("departure into a subtrahend: shadow rays from a hole's wall start where they leave the hole",
          "[render][oracle]") {
    // The answer with the departure must be the full evaluation's; and
    // point membership (no ray code) finds no point of the solid on the
    // ray while it is still inside the hole's leaf.
    const bool use_float = GENERATE(false, true);
    const bool alone = GENERATE(false, true);
    for (const double k : {1e-3, 1.0, 1e4}) {
        const glm::dvec3 c(100 * k, -60 * k, 30 * k);
        const csg::Scene s = make_scene(hollows(translate(c.x, c.y, c.z) * scale(k, k, k), alone));
        const render::CsgTracer tracer(s, use_float);
        render::TraceScratch scratch;
        RandomCsg g(7);
        int taken = 0, blocked = 0, unmarked = 0;
        for (int i = 0; i < 4000; ++i) {
            const glm::dvec3 aim = c + k * glm::dvec3(g.uni(-1.2, 5.2), g.uni(-1.2, 5.2), g.uni(-1.2, 1.2));
            const glm::dvec3 o = aim + 12 * k * glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-0.3, 1)) + 1e-3);
            const glm::dvec3 d = aim - o;
            render::TraceHit hit;
            if (!tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, scratch) || !hit.surface.flip) continue;
            const glm::dvec3 p = o + hit.t * d;
            const glm::dvec3 n = tracer.normal(hit, p);
            if (glm::dot(n, d) > 0) continue;  // the shader turns n: no departure there
            const render::Departure from = tracer.departure(hit, n);
            if (from.hollow == csg::kNone) ++unmarked;
            const glm::dvec3 origin = p + tracer.surface_offset(hit, p) * n;
            const csg::Leaf& hole = s.leaves[hit.surface.leaf];
            for (int j = 0; j < 6; ++j) {
                glm::dvec3 l = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
                if (glm::dot(l, n) < 0) l = -l;
                if (j % 2 == 1) l = glm::normalize(l - glm::dot(l, n) * n + std::pow(10.0, -g.uni(1, 9)) * n);
                const double tfar = k * g.uni(0.05, 6);
                const render::TraceRay ray{origin, l, 0, tfar};
                const bool full = tracer.occluded(ray, scratch);
                INFO("float " << use_float << " scale " << k << " ray " << i << " shadow " << j);
                CHECK(tracer.occluded(ray, scratch, &from) == full);
                blocked += full ? 1 : 0;
                if (from.hollow == csg::kNone) continue;
                ++taken;
                for (int m = 1; m <= 200; ++m) {
                    const glm::dvec3 x = origin + (tfar * m / 200) * l;
                    if (!csg::contains(hole, hole.object_from_world.point(x))) break;
                    CHECK_FALSE(csg::contains(s, x));
                }
            }
        }
        INFO((alone ? "the plate alone: " : "") << taken << " taken, " << blocked << " blocked, " << unmarked
                                                 << " hits on unmarked subtrahends");
        CHECK(taken > (alone ? 300 : 1000));
        CHECK(blocked > (alone ? 100 : 300));
        if (!alone) CHECK(unmarked > 20);  // the block's hole (under a union) is never taken
    }
}

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

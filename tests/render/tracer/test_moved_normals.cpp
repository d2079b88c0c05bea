// The world normal of a leaf that is only moved (no rotation or scale) on
// a box face or a straight cylinder's side takes a short path
// (tracer/surface_normal.cpp): a box's face normal is already a unit axis,
// and a straight side's ρ is the normal's length. Against the closed forms
// (the face's axis; the radial direction from the cylinder's axis, turned
// into the hole for a subtrahend) and against the general path's formula
// (object_normal, then n / |n|) bit for bit, on a plate with drilled holes
// and a square notch (flipped box faces) at 1e-3, 1 and 1e4 scale far from
// the origin, hit by rays from every side.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "render/primitives/primitives.hpp"
#include "render/tracer/tracer.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::PrimKind;

namespace {

// The general path (surface_normal.cpp without the short one) for a moved leaf.
glm::dvec3 general_normal(const csg::Leaf& leaf, const render::TraceHit& hit, const glm::dvec3& p) {
    const glm::dvec3 q = p + leaf.object_from_world.offset;
    glm::dvec3 n = csg::object_normal(leaf, q, hit.surface.part);
    const double len = glm::length(n);
    n = len > 0 ? n / len : glm::dvec3(0, 0, 1);
    return hit.surface.flip ? -n : n;
}

bool same_bits(const glm::dvec3& a, const glm::dvec3& b) {
    for (int i = 0; i < 3; ++i)
        if (std::signbit(a[i]) != std::signbit(b[i]) || !(a[i] == b[i])) return false;
    return true;
}

}  // namespace

TEST_CASE("normals of moved boxes and straight cylinders: closed forms and the general path's bits", "[render][oracle]") {
    for (const double k : {1e-3, 1.0, 1e4}) {
        const glm::dvec3 c(300 * k, -200 * k, 50 * k);
        std::vector<Tree> kids{leaf(box({0, 0, 0}, {4 * k, 4 * k, k}, translate(c.x, c.y, c.z)))};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                kids.push_back(leaf(make_leaf(PrimKind::Cylinder, {0, 3 * k, 0.3 * k, 0.3 * k},
                                              translate(c.x + (i + 0.5) * k, c.y + (j + 0.5) * k, c.z - k))));
        // A square notch in one edge: flipped box faces.
        kids.push_back(leaf(box({-0.5 * k, 1.7 * k, 0.4 * k}, {0.9 * k, 2.6 * k, 2 * k}, translate(c.x, c.y, c.z))));
        const csg::Scene s = make_scene(op(csg::Op::Difference, kids));
        const render::CsgTracer tracer(s, false);
        render::TraceScratch scratch;
        std::mt19937_64 rng(1805);
        std::uniform_real_distribution<double> u(-1, 1);
        int faces = 0, walls = 0, notch = 0;
        for (int i = 0; i < 20000; ++i) {
            const glm::dvec3 aim = c + k * glm::dvec3(2 + 2.2 * u(rng), 2 + 2.2 * u(rng), 0.5 + 0.6 * u(rng));
            const glm::dvec3 o = aim + 20 * k * glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + 1e-3);
            render::TraceHit hit;
            if (!tracer.intersect(render::TraceRay{o, aim - o, 0, std::numeric_limits<double>::infinity()}, hit, scratch)) continue;
            const glm::dvec3 p = o + hit.t * (aim - o);
            const glm::dvec3 n = tracer.normal(hit, p);
            const csg::Leaf& leaf = s.leaves[hit.surface.leaf];
            INFO("scale " << k << " ray " << i << " leaf " << hit.surface.leaf << " part " << int(hit.surface.part));
            CHECK(same_bits(n, general_normal(leaf, hit, p)));
            if (leaf.kind == PrimKind::Box) {
                ++faces;
                notch += hit.surface.flip;
                const int axis = hit.surface.part % 3;
                glm::dvec3 want(0.0);
                want[axis] = (hit.surface.part < 3) != bool(hit.surface.flip) ? -1 : 1;
                CHECK(n == want);
            } else if (hit.surface.part == 0) {  // the side: into the hole
                ++walls;
                const glm::dvec3 axis = leaf.world_from_object.point(glm::dvec3(0.0));
                const glm::dvec3 want = -glm::normalize(glm::dvec3(p.x - axis.x, p.y - axis.y, 0));
                CHECK(glm::length(n - want) < 1e-9);
                CHECK(std::abs(glm::length(n) - 1) < 1e-15);
            }
        }
        INFO(faces << " on faces (" << notch << " in the notch), " << walls << " on walls");
        CHECK(faces > 3000);
        CHECK(notch > 100);
        CHECK(walls > 1000);
    }
}

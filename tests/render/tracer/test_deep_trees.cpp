// Deeply nested operations (lowering allows source nesting up to 256) must
// render without exhausting the stack, including nested Embree queries.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

TEST_CASE("a 256-deep chain of wide differences renders", "[render][deep]") {
    // d_k = sphere_k − (d_{k+1}, 9 small spheres): every level has its own
    // subtrahend BVH, so the queries nest 256 deep.
    Tree t = leaf(sphere(0.05));
    for (int k = 0; k < 256; ++k) {
        const double r = 0.1 + 0.004 * k;
        Tree d = op(Op::Difference, {leaf(sphere(r)), std::move(t)});
        for (int j = 0; j < 9; ++j) d.kids.push_back(leaf(sphere(0.01, translate(r * std::cos(j), -r * std::sin(j), 0.9 * r))));
        t = op(Op::Intersection, {std::move(d), leaf(box(glm::dvec3(-2), glm::dvec3(2)))});
    }
    csg::Scene s = make_scene(t);
    s.camera.position = {0, -4, 0.5};
    render::RenderOptions o;
    o.width = 16;
    o.height = 12;
    o.threads = 2;
    o.aov = render::Aov::Depth;
    const render::Image im = render::render(s, o);
    // The outermost shell is what the centre pixel sees.
    const double r_out = 0.1 + 0.004 * 255;
    CHECK(im.at(8, 6, 0) > 4 - r_out - 0.2);
    CHECK(im.at(8, 6, 0) < 4);
}

// Work per ray must not grow with what lies behind the first hit or with the
// number of subtrahends a ray passes (the tracer's culling promises).
#include <catch2/catch.hpp>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

// n spheres in a row along the view axis, seen end-on: all but the first are
// hidden behind it.
csg::Scene row_of_spheres(int n) {
    std::vector<Tree> kids;
    for (int i = 0; i < n; ++i) kids.push_back(leaf(sphere(1.0, translate(0, 3.0 * i, 0))));
    csg::Scene s = make_scene(op(Op::Union, kids));
    s.camera.position = {0, -6, 0};
    s.camera.look_at = {0, 0, 0};
    return s;
}

// A slab minus an n × n grid of cylinders (docs/spec.md §9 "holes", radius 4/n).
csg::Scene holes(int n) {
    std::vector<Tree> kids{leaf(box({0, 0, 0}, {10, 10, 1}))};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            kids.push_back(leaf(make_leaf(csg::PrimKind::Cylinder, {0, 3, 4.0 / n, 4.0 / n},
                                          translate((i + 0.5) * 10 / n, (j + 0.5) * 10 / n, -1))));
    csg::Scene s = make_scene(op(Op::Difference, kids));
    s.camera.position = {14, -6, 12};  // oblique: chords through the slab cross many holes
    s.camera.look_at = {5, 5, 0.5};
    return s;
}

double tests_per_primary_ray(const csg::Scene& s) {
    render::RenderOptions o;
    o.width = 40;
    o.height = 30;
    o.aov = render::Aov::Depth;  // primary rays only
    render::RenderStats st;
    render::render(s, o, &st);
    return double(st.interval_tests) / double(st.primary_rays);
}

}  // namespace

TEST_CASE("hidden units behind the first hit are never intersected", "[render][cost]") {
    const double few = tests_per_primary_ray(row_of_spheres(3));
    const double many = tests_per_primary_ray(row_of_spheres(2000));
    CHECK(many <= few * 1.05 + 0.01);
    // And the hits AOV agrees: one sphere's interval per covered pixel.
    render::RenderOptions o;
    o.width = 20;
    o.height = 20;
    o.aov = render::Aov::Hits;
    const render::Image im = render::render(row_of_spheres(2000), o);
    CHECK(im.at(10, 10, 0) == 1.0f);
}

TEST_CASE("first hits through a slab with n² holes cost about the same for any n", "[render][cost]") {
    const double n10 = tests_per_primary_ray(holes(10));
    const double n80 = tests_per_primary_ray(holes(80));
    CHECK(n10 > 0.3);
    CHECK(n80 <= n10 * 1.5);
}

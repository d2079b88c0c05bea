// Hidden (tag [.demo]): writes a few images to /tmp for eyeballing.
#include <catch2/catch.hpp>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

TEST_CASE("demo image", "[.demo]") {
    csg::Material red, blue;
    red.color = {0.8, 0.1, 0.1};
    red.interior = {0.9, 0.8, 0.1};
    blue.color = {0.1, 0.2, 0.8};
    blue.reflect = 0.3;
    csg::Scene s = make_scene(
        op(Op::Union, {op(Op::Difference, {leaf(sphere(1.2, glm::dmat4(1.0), 0)), leaf(box({0, -2, 0}, {2, 0, 2}, glm::dmat4(1.0), 1))}),
                       leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, -1.2}, glm::dmat4(1.0), 1))}),
        {red, blue});
    s.camera.position = {3, -5, 3};
    render::RenderOptions o;
    o.width = 400;
    o.height = 300;
    o.spp = 4;
    render::RenderStats st;
    const render::Image im = render::render(s, o, &st);
    render::write_image(im, "/tmp/kerf_demo.png");
    WARN("rays " << st.rays() << " seconds " << st.seconds);
}

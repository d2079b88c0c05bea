// Cameras per docs/spec.md §6, checked against the written rules, and image
// orientation (row 0 on top, column 0 on the left) through whole renders.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/camera.hpp"
#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;

TEST_CASE("perspective rays: pixel centres on a plane 2·tan(fov/2) high at distance 1", "[camera]") {
    csg::Camera c;
    c.position = {1, 2, 3};
    c.look_at = {1, 12, 3};  // forward +y, up +z: right = forward × up = +x
    c.fov = 60;
    const int W = 40, H = 20;
    const render::CameraModel cam(c, W, H);
    glm::dvec3 o, d;
    cam.ray(W / 2.0, H / 2.0, o, d);  // the image centre looks straight ahead
    CHECK(o == c.position);
    CHECK(d.x == Approx(0).margin(1e-15));
    CHECK(d.y == Approx(1));
    const double h = 2 * std::tan(glm::radians(30.0)), w = h * W / H;
    cam.ray(0, 0, o, d);  // top-left corner of the image
    CHECK(d.x / d.y == Approx(-w / 2));
    CHECK(d.z / d.y == Approx(h / 2));
    cam.ray(W, H, o, d);  // bottom-right corner
    CHECK(d.x / d.y == Approx(w / 2));
    CHECK(d.z / d.y == Approx(-h / 2));
    CHECK(glm::length(d) == Approx(1));
}

TEST_CASE("orthographic rays: parallel, from a `height`-high image plane", "[camera]") {
    csg::Camera c;
    c.position = {0, -10, 0};
    c.look_at = {0, 0, 0};
    c.orthographic = true;
    c.height = 4;
    const render::CameraModel cam(c, 30, 20);
    glm::dvec3 o, d;
    cam.ray(0, 0, o, d);
    CHECK(d == glm::dvec3(0, 1, 0));
    CHECK(o.x == Approx(-3));
    CHECK(o.z == Approx(2));
    CHECK(o.y == Approx(-10));
}

TEST_CASE("an object right of and above the view centre lands top-right", "[camera]") {
    for (bool ortho : {false, true}) {
        csg::Scene s = make_scene(leaf(sphere(0.4, translate(1.5, 0, 1.0))));
        s.camera.position = {0, -8, 0};
        s.camera.look_at = {0, 0, 0};
        s.camera.orthographic = ortho;
        s.camera.height = 6;
        render::RenderOptions o;
        o.width = 40;
        o.height = 30;
        o.aov = render::Aov::Depth;
        const render::Image im = render::render(s, o);
        double sx = 0, sy = 0, n = 0, nearest = 1e9;
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x)
                if (std::isfinite(im.at(x, y, 0))) sx += x, sy += y, n += 1, nearest = std::min(nearest, double(im.at(x, y, 0)));
        REQUIRE(n > 3);
        CHECK(sx / n > 25);
        CHECK(sy / n < 12);
        // Depth: from the camera position (perspective) or the image plane (orthographic).
        if (ortho) CHECK(nearest == Approx(8 - 0.4).margin(0.03));
        else CHECK(nearest == Approx(glm::length(glm::dvec3(1.5, 8, 1.0)) - 0.4).margin(0.03));
    }
}

// Shading closed forms: Lambert + ambient on a lit plane, hard shadows,
// mirror reflection, background on a miss.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

csg::Material flat(glm::dvec3 c, double reflect = 0) {
    csg::Material m;
    m.color = m.interior = c;
    m.specular = 0;
    m.diffuse = 1;
    m.reflect = reflect;
    return m;
}

}  // namespace

TEST_CASE("a ground plane is lit by Lambert's law and shadowed below a sphere", "[render][shading]") {
    // Ground z <= 0 (a half-space unit, never in the BVH), ball above it,
    // distant light straight down; orthographic camera looking down too.
    const Tree t = op(Op::Union, {leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0}, glm::dmat4(1.0), 0)),
                                  leaf(sphere(1, translate(0, 0, 3), 1))});
    csg::Scene s = make_scene(t, {flat({0.5, 0.5, 0.5}), flat({1, 0, 0})});
    s.camera.position = {0, -0.001, 10};
    s.camera.look_at = {0, 0, 0};
    s.camera.up = {0, 1, 0};
    s.camera.orthographic = true;
    s.camera.height = 8;
    s.lights = {csg::Light{true, {}, {0, 0, -1}, {1, 1, 1}, 0.8}};
    render::RenderOptions o;
    o.width = o.height = 41;
    const render::Image im = render::render(s, o);
    // Far corner: ground, lit: ambient 0.1·albedo + 0.8·albedo·(n·l = 1).
    CHECK(im.at(1, 1, 0) == Approx(0.1 * 0.5 + 0.8 * 0.5).epsilon(1e-5));
    // Centre: the top of the red ball.
    CHECK(im.at(20, 20, 0) == Approx(0.1 + 0.8).epsilon(1e-3));
    CHECK(im.at(20, 20, 1) == 0.0f);
    // With the light straight down the shadow hides under the ball: tilt the
    // light 45° and look at the shadow instead.
    s.lights = {csg::Light{true, {}, {1, 0, -1}, {1, 1, 1}, 0.8}};
    const render::Image tilted = render::render(s, o);
    // The shadow's centre is at x = +3 (height 3, 45°): pixel 20 + 3·41/8 ≈ 35.
    CHECK(tilted.at(35, 20, 0) == Approx(0.1 * 0.5).epsilon(1e-5));  // ambient only
    CHECK(tilted.at(5, 20, 0) == Approx(0.1 * 0.5 + 0.8 * 0.5 * std::sqrt(0.5)).epsilon(1e-5));
}

TEST_CASE("a mirror shows what it reflects, misses show the background", "[render][shading]") {
    // Perfect mirror plane z <= 0, camera looking straight down at it through
    // nothing: the reflected ray goes straight up and hits a green ceiling box.
    const Tree t = op(Op::Union, {leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0}, glm::dmat4(1.0), 0)),
                                  leaf(box({-50, -50, 20}, {50, 50, 21}, glm::dmat4(1.0), 1))});
    csg::Scene s = make_scene(t, {flat({1, 1, 1}, 1.0), flat({0, 1, 0})});
    s.camera.position = {0, -0.001, 10};
    s.camera.look_at = {0, 0, 0};
    s.camera.up = {0, 1, 0};
    s.camera.orthographic = true;
    s.camera.height = 4;
    s.lights = {csg::Light{false, {0, 0, 10}, {}, {1, 1, 1}, 1}};
    s.background = {0.25, 0.5, 0.75};
    render::RenderOptions o;
    o.width = o.height = 9;
    const render::Image im = render::render(s, o);
    // The ceiling's underside faces the light at z = 10 (distance 10): lit by
    // n·l = 1, so green = 0.1 + 1 (ambient + diffuse).
    CHECK(im.at(4, 4, 0) == Approx(0).margin(1e-6));
    CHECK(im.at(4, 4, 1) == Approx(1.1).epsilon(1e-5));
    o.preview = true;  // no reflections: the mirror's own (white) shading
    const render::Image pre = render::render(s, o);
    CHECK(pre.at(4, 4, 0) == Approx(1.1).epsilon(1e-5));
    s.root = csg::kNone;
    const render::Image none = render::render(s, o);
    CHECK(none.at(4, 4, 2) == 0.75f);
}

TEST_CASE("the Blinn–Phong highlight is specular·(n·h)^shininess, whole and fractional exponents", "[render][shading]") {
    // Ground plane seen straight down by an orthographic camera; a distant
    // light tilted by 30° from the vertical: n·l = cos 30°, and the half
    // vector between l and the view (straight up) makes 15° with n.
    const double deg = 30, nl = std::cos(glm::radians(deg)), nh = std::cos(glm::radians(deg / 2));
    for (const double shininess : {1.0, 7.0, 32.0, 100.0, 12.5, 2000.0}) {
        csg::Material m = flat({0.5, 0.5, 0.5});
        m.diffuse = 0.6;
        m.specular = 0.4;
        m.shininess = shininess;
        csg::Scene s = make_scene(leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0})), {m});
        s.camera.position = {0, -0.001, 10};
        s.camera.look_at = {0, 0, 0};
        s.camera.up = {0, 1, 0};
        s.camera.orthographic = true;
        s.camera.height = 2;
        s.lights = {csg::Light{true, {}, {std::sin(glm::radians(deg)), 0, -nl}, {1, 1, 1}, 1}};
        render::RenderOptions o;
        o.width = o.height = 3;
        const render::Image im = render::render(s, o);
        INFO("shininess " << shininess);
        CHECK(im.at(1, 1, 0) == Approx(0.1 * 0.5 + 0.6 * nl * 0.5 + 0.4 * std::pow(nh, shininess)).epsilon(1e-5));
    }
}

TEST_CASE("the highlight's half vector uses the unit view, also for a pinhole camera's unnormalised rays", "[render][shading]") {
    // A pinhole camera 10 above the ground plane looking straight down,
    // fov 90° on a 3×3 image: pixel (0, 1) looks along d = forward ± (2/3)·right,
    // |d| = √13/3 (pinhole model: half height tan 45° = 1), so the view is
    // (∓2, 0, 3)/√13 — the same n·h for either sign. A distant light
    // tilted 30° along y. Shading normalises nothing it is given here:
    // a half vector built from d without its length misses the closed form.
    const double deg = 30, nl = std::cos(glm::radians(deg));
    const glm::dvec3 l(0, -std::sin(glm::radians(deg)), nl), view = glm::dvec3(2, 0, 3) / std::sqrt(13.0);
    const double nh = glm::normalize(l + view).z;
    for (const double shininess : {7.0, 32.0, 12.5}) {
        csg::Material m = flat({0.5, 0.5, 0.5});
        m.diffuse = 0.6;
        m.specular = 0.4;
        m.shininess = shininess;
        csg::Scene s = make_scene(leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0})), {m});
        s.camera.position = {0, 0, 10};
        s.camera.look_at = {0, 0, 0};
        s.camera.up = {0, 1, 0};
        s.camera.fov = 90;
        s.lights = {csg::Light{true, {}, -l, {1, 1, 1}, 1}};
        render::RenderOptions o;
        o.width = o.height = 3;
        const render::Image im = render::render(s, o);
        INFO("shininess " << shininess);
        CHECK(im.at(0, 1, 0) == Approx(0.1 * 0.5 + 0.6 * nl * 0.5 + 0.4 * std::pow(nh, shininess)).epsilon(1e-6));
        CHECK(im.at(2, 1, 0) == Approx(im.at(0, 1, 0)).epsilon(1e-6));
    }
}

// Surface rules of the CSG tracer: cut faces show the minuend's interior with
// the final solid's normal, A − A is empty, flush faces leave no speckles.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

render::RenderOptions options(int w, int h, render::Aov aov) {
    render::RenderOptions o;
    o.width = w;
    o.height = h;
    o.aov = aov;
    return o;
}

csg::Material flat(glm::dvec3 color, glm::dvec3 interior) {
    csg::Material m;
    m.color = color;
    m.interior = interior;
    m.specular = 0;  // pure albedo: the pixel's hue tells which colour was used
    return m;
}

// A looked-at scene: camera on -y, light at the camera.
csg::Scene front_view(const Tree& t, std::vector<csg::Material> mats) {
    csg::Scene s = make_scene(t, std::move(mats));
    s.camera.position = {0, -6, 0};
    s.camera.look_at = {0, 0, 0};
    s.lights = {csg::Light{false, {0, -6, 0}, {0, 0, -1}, {1, 1, 1}, 1}};
    s.background = {0, 0, 0};
    return s;
}

const glm::dmat4 kTilt = translate(0.1, 0.2, -0.05) * rotate_deg(23, glm::normalize(glm::dvec3(1, 2, 3)));

}  // namespace

TEST_CASE("a cut face shows the minuend's interior colour and the final solid's normal", "[render][csg]") {
    // Red sphere (interior green) minus a blue box removing its front half.
    const Tree t = op(Op::Difference, {leaf(sphere(1.0, glm::dmat4(1.0), 0)), leaf(box({-2, -2, -2}, {2, 0, 2}, glm::dmat4(1.0), 1))});
    const csg::Scene s = front_view(t, {flat({1, 0, 0}, {0, 1, 0}), flat({0, 0, 1}, {0, 0, 1})});
    const render::Image color = render::render(s, options(21, 21, render::Aov::None));
    const render::Image normal = render::render(s, options(21, 21, render::Aov::Normal));
    const render::Image depth = render::render(s, options(21, 21, render::Aov::Depth));
    CHECK(color.at(10, 10, 0) == 0.0f);
    CHECK(color.at(10, 10, 1) > 0.5f);
    CHECK(color.at(10, 10, 2) == 0.0f);
    CHECK(normal.at(10, 10, 0) == Approx(0).margin(1e-12));
    CHECK(normal.at(10, 10, 1) == Approx(-1));
    CHECK(normal.at(10, 10, 2) == Approx(0).margin(1e-12));
    CHECK(depth.at(10, 10, 0) == Approx(6.0).epsilon(1e-9));
}

TEST_CASE("union and intersection surfaces show their own primitive's exterior", "[render][csg]") {
    const std::vector<csg::Material> mats = {flat({1, 0, 0}, {0, 1, 0}), flat({0, 0, 1}, {1, 1, 0})};
    SECTION("union: the box in front is blue") {
        const Tree t = op(Op::Union, {leaf(sphere(1.0, glm::dmat4(1.0), 0)), leaf(box({-0.3, -1.5, -0.3}, {0.3, 0, 0.3}, glm::dmat4(1.0), 1))});
        const render::Image im = render::render(front_view(t, mats), options(21, 21, render::Aov::None));
        CHECK(im.at(10, 10, 2) > 0.5f);
        CHECK(im.at(10, 10, 0) == 0.0f);
        CHECK(im.at(10, 10, 1) == 0.0f);
        CHECK(im.at(10, 7, 0) > 0.3f);  // the sphere around it: red
        CHECK(im.at(10, 7, 2) == 0.0f);
    }
    SECTION("intersection: the flat face belongs to the box (blue), not a cut") {
        const Tree t = op(Op::Intersection, {leaf(sphere(1.0, glm::dmat4(1.0), 0)), leaf(box({-2, 0, -2}, {2, 2, 2}, glm::dmat4(1.0), 1))});
        const render::Image im = render::render(front_view(t, mats), options(21, 21, render::Aov::None));
        CHECK(im.at(10, 10, 2) > 0.5f);
        CHECK(im.at(10, 10, 0) == 0.0f);
        CHECK(im.at(10, 10, 1) == 0.0f);
    }
}

TEST_CASE("A minus A renders empty", "[render][csg]") {
    const csg::Leaf a = sphere(1.0, kTilt * scale(1, 0.7, 1.2));
    const csg::Leaf b = box({-0.8, -0.6, -0.7}, {0.9, 0.5, 0.6}, kTilt);
    for (const csg::Leaf& l : {a, b}) {
        const csg::Scene s = front_view(op(Op::Difference, {leaf(l), leaf(l)}), {csg::Material{}});
        const render::Image im = render::render(s, options(40, 30, render::Aov::Depth));
        int hits = 0;
        for (float v : im.pixels) hits += std::isfinite(v) ? 1 : 0;
        CHECK(hits == 0);
        // ... and A alone is visible, so the empty image is not vacuous.
        const render::Image whole = render::render(front_view(leaf(l), {csg::Material{}}), options(40, 30, render::Aov::Depth));
        int whole_hits = 0;
        for (float v : whole.pixels) whole_hits += std::isfinite(v) ? 1 : 0;
        CHECK(whole_hits > 100);
    }
}

TEST_CASE("differences with flush faces leave no speckles", "[render][csg]") {
    // M = unit box under a tilt; S = its right half, built through another
    // transform so every shared face is computed with different round-off.
    // M − S must equal the left half exactly, pixel for pixel.
    const glm::dmat4 m = kTilt * scale(1.3, 1.1, 0.9);
    const Tree t = op(Op::Difference, {leaf(box({-1, -1, -1}, {1, 1, 1}, m)),
                                       leaf(box({-1, -1, -1}, {1, 1, 1}, m * translate(0.5, 0, 0) * scale(0.5, 1, 1)))});
    const Tree expected = leaf(box({-1, -1, -1}, {0, 1, 1}, m));
    const int W = 64, H = 48;
    const render::Image got = render::render(front_view(t, {csg::Material{}}), options(W, H, render::Aov::Depth));
    const render::Image want = render::render(front_view(expected, {csg::Material{}}), options(W, H, render::Aov::Depth));
    const render::Image got_n = render::render(front_view(t, {csg::Material{}}), options(W, H, render::Aov::Normal));
    const render::Image want_n = render::render(front_view(expected, {csg::Material{}}), options(W, H, render::Aov::Normal));
    int mismatches = 0, hits = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float a = got.at(x, y, 0), b = want.at(x, y, 0);
            hits += std::isfinite(b);
            bool same = std::isfinite(a) == std::isfinite(b) && (!std::isfinite(a) || std::abs(a - b) <= 1e-6f * b);
            for (int c = 0; c < 3; ++c) same = same && std::abs(got_n.at(x, y, c) - want_n.at(x, y, c)) < 1e-6f;
            mismatches += !same;
        }
    CHECK(hits > 200);
    CHECK(mismatches == 0);
}

// Closed-form checks: depth of a sphere and a box seen head-on, A − A empty,
// cut faces, flush faces.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {
render::RenderOptions small(int w, int h, render::Aov aov = render::Aov::None) {
    render::RenderOptions o;
    o.width = w;
    o.height = h;
    o.aov = aov;
    o.threads = 1;
    return o;
}
}  // namespace

TEST_CASE("sphere depth matches the closed form at every pixel", "[render]") {
    csg::Scene s = make_scene(leaf(sphere(1.5, translate(0.2, 0, 0.1))));
    s.camera.position = {0, -6, 2};
    const int W = 40, H = 30;
    const render::Image im = render::render(s, small(W, H, render::Aov::Depth));
    REQUIRE(im.width == W);
    REQUIRE(im.channels == 1);
    // The same rays, by hand: camera basis per docs/spec.md §6.
    const glm::dvec3 pos = s.camera.position, c(0.2, 0, 0.1);
    const glm::dvec3 f = glm::normalize(s.camera.look_at - pos);
    const glm::dvec3 r = glm::normalize(glm::cross(f, s.camera.up));
    const glm::dvec3 u = glm::cross(r, f);
    const double hh = std::tan(glm::radians(s.camera.fov) / 2), hw = hh * W / H;
    int hits = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const glm::dvec3 d = glm::normalize(f + ((x + 0.5) / W * 2 - 1) * hw * r + (1 - (y + 0.5) / H * 2) * hh * u);
            const glm::dvec3 oc = pos - c;
            const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - 1.5 * 1.5);
            const float got = im.at(x, y, 0);
            if (disc <= 1e-9) {
                CHECK(std::isinf(got));
            } else {
                ++hits;
                CHECK(got == Approx(-b - std::sqrt(disc)).epsilon(1e-6));
            }
        }
    CHECK(hits > 100);
}

// fog(distance, color) against its closed form (csg::Fog): a surface at
// distance s keeps exp(−s/distance) of its colour, the rest is the fog's;
// a ray that escapes sees the fog colour alone (POV-Ray: the background is
// at infinite distance). The surface is a black emitter, so its own colour
// is exactly its emission whatever the light.
#include <catch2/catch.hpp>

#include <cmath>

#include "csg/srgb.hpp"
#include "tests/render/same_bytes.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

// A floor (top at z = 0) seen straight down from `above` by an orthographic
// camera whose view is wider than the floor: the outer pixels miss it.
csg::Scene fogged_floor(double above, const glm::dvec3& emission) {
    csg::Material m;
    m.color = glm::dvec3(0.0);
    m.specular = 0;
    m.emission = emission;
    csg::Scene s = make_scene(leaf(box({-1, -1, -1}, {1, 1, 0})), {m});
    s.lights.clear();
    s.background = {0.9, 0.1, 0.1};
    look_down(s, {0, 0, 0}, above, 4);
    return s;
}

}  // namespace

TEST_CASE("fog: a plane at distance s keeps exp(-s/distance) of its colour, the background is all fog", "[render][fog]") {
    const glm::dvec3 e(0.8, 0.4, 0.1), fog(0.2, 0.5, 0.7);
    for (double above : {0.5, 3.0, 10.0}) {
        for (double distance : {1.0, 4.0, 40.0}) {
            csg::Scene s = fogged_floor(above, e);
            s.fog = {distance, fog};
            render::RenderOptions o;
            o.width = o.height = 8;
            const render::Image im = render::render(s, o);
            const double k = std::exp(-above / distance);
            INFO("above " << above << " distance " << distance);
            for (int c = 0; c < 3; ++c) {
                // Pixel (3, 3) looks at the floor, (0, 0) past it.
                CHECK(im.at(3, 3, c) == Approx(e[c] * k + fog[c] * (1 - k)).margin(1e-6));
                CHECK(im.at(0, 0, c) == Approx(fog[c]).margin(1e-7));
            }
            // 8-bit output encodes the fogged linear value with the sRGB curve.
            o.srgb8 = true;
            const render::Image bytes = render::render(s, o);
            const std::size_t at = (3 * 8 + 3) * 3;
            for (int c = 0; c < 3; ++c) {
                const double want = 255 * csg::linear_to_srgb(e[c] * k + fog[c] * (1 - k));
                CHECK(std::abs(double(bytes.srgb8[at + c]) - want) <= 0.5 + 1e-9);
            }
        }
    }
}

TEST_CASE("fog: none when the scene has none, same bytes on any thread count", "[render][fog]") {
    csg::Scene s = fogged_floor(3, {0.5, 0.5, 0.5});
    render::RenderOptions o;
    o.width = o.height = 8;
    const render::Image clear = render::render(s, o);
    CHECK(clear.at(3, 3, 0) == Approx(0.5).margin(1e-7));
    CHECK(clear.at(0, 0, 0) == Approx(0.9).margin(1e-7));
    s.fog = {2, {1, 1, 1}};
    // Perspective rays (unnormalised directions) travel the Euclidean distance.
    s.camera.orthographic = false;
    s.camera.fov = 40;
    const render::Image persp = render::render(s, o);
    glm::dvec3 org, dir;
    // Pixel (3, 3)'s centre ray hits z = 0 after |d|·3/|d_z| along its unit direction.
    const double h = std::tan(glm::radians(20.0));
    const double u = (3.5 / 8 * 2 - 1) * h, v = (1 - 3.5 / 8 * 2) * h;
    const double dist = 3 * std::sqrt(1 + u * u + v * v);
    const double k = std::exp(-dist / 2);
    CHECK(persp.at(3, 3, 0) == Approx(0.5 * k + (1 - k)).margin(1e-6));
    (void)org, (void)dir;
    o.spp = 4;
    const auto [one, two] = on_1_and_2_threads(s, o);
    CHECK(same_bytes(one, two));
}

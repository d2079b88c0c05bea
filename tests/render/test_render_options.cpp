// Rendering options: determinism across thread counts, crops, progress,
// stats, preview and option validation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "render/camera.hpp"
#include "render/render.hpp"
#include "tests/render/same_bytes.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

csg::Scene busy_scene() {
    csg::Material shiny;
    shiny.color = {0.7, 0.6, 0.2};
    shiny.interior = {0.2, 0.7, 0.3};
    shiny.reflect = 0.4;
    csg::Material matte;
    matte.color = {0.3, 0.4, 0.8};
    Tree t = op(Op::Union, {op(Op::Difference, {leaf(sphere(1.2, glm::dmat4(1.0), 0)),
                                                leaf(box({0, -2, 0}, {2, 0, 2}, rotate_deg(10, {0, 0, 1}), 1))}),
                            leaf(sphere(0.5, translate(1.6, 0.5, -0.6), 1)),
                            leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, -1.2}, glm::dmat4(1.0), 1))});
    csg::Scene s = make_scene(t, {shiny, matte});
    s.camera.position = {3, -5, 3};
    s.lights.push_back(csg::Light{true, {}, {-1, 1, -2}, {0.5, 0.5, 0.6}, 0.7});
    return s;
}

}  // namespace

TEST_CASE("the same seed gives the same bytes with 1 and 2 threads", "[render][determinism]") {
    const csg::Scene s = busy_scene();
    render::RenderOptions o;
    o.width = 64;
    o.height = 48;
    o.spp = 5;
    o.seed = 42;
    const auto [one, two] = on_1_and_2_threads(s, o);
    CHECK(same_bytes(one, two));
    o.threads = 2;
    o.seed = 43;  // and the seed matters (jitter is real)
    const render::Image other = render::render(s, o);
    CHECK_FALSE(same_bytes(one, other));
}

TEST_CASE("crops reassemble into the whole image exactly", "[render][crop]") {
    const csg::Scene s = busy_scene();
    render::RenderOptions o;
    o.width = 50;
    o.height = 40;
    o.spp = 3;
    o.seed = 7;
    const render::Image whole = render::render(s, o);
    render::Image assembled = whole;
    std::fill(assembled.pixels.begin(), assembled.pixels.end(), -1.0f);
    const std::array<int, 4> crops[] = {{0, 0, 17, 40}, {17, 0, 50, 13}, {17, 13, 50, 40}};
    for (const auto& c : crops) {
        o.crop = c;
        const render::Image part = render::render(s, o);
        REQUIRE(part.width == c[2] - c[0]);
        REQUIRE(part.height == c[3] - c[1]);
        for (int y = 0; y < part.height; ++y)
            for (int x = 0; x < part.width; ++x)
                for (int ch = 0; ch < 3; ++ch) assembled.at(c[0] + x, c[1] + y, ch) = part.at(x, y, ch);
    }
    CHECK(same_bytes(whole, assembled));
}

TEST_CASE("progress reaches 1 in order, stats count the rays", "[render]") {
    const csg::Scene s = busy_scene();
    render::RenderOptions o;
    o.width = 100;
    o.height = 70;
    o.spp = 2;
    std::vector<double> seen;
    render::RenderStats st;
    render::render(s, o, &st, [&](double f) { seen.push_back(f); });
    REQUIRE(!seen.empty());
    CHECK(seen.back() == 1.0);
    CHECK(std::is_sorted(seen.begin(), seen.end()));
    CHECK(st.primary_rays == 100u * 70u * 2u);
    CHECK(st.shadow_rays > 0);
    CHECK(st.reflect_rays > 0);
    CHECK(st.difference_ops > 0);
    CHECK(st.interval_tests >= st.primary_rays / 4);
    CHECK(st.seconds > 0);

    o.preview = true;  // 1 spp, no reflections
    render::render(s, o, &st);
    CHECK(st.primary_rays == 100u * 70u);
    CHECK(st.reflect_rays == 0);
}

TEST_CASE("bad options are rejected", "[render]") {
    const csg::Scene s = busy_scene();
    render::RenderOptions o;
    o.width = 0;
    CHECK_THROWS_AS(render::render(s, o), std::invalid_argument);
    o.width = 10;
    o.height = 10;
    o.crop = std::array<int, 4>{5, 5, 11, 8};
    CHECK_THROWS_AS(render::render(s, o), std::invalid_argument);
    o.crop = std::array<int, 4>{5, 5, 5, 8};
    CHECK_THROWS_AS(render::render(s, o), std::invalid_argument);
}

TEST_CASE("an empty scene renders the background", "[render]") {
    csg::Scene s = busy_scene();
    s.root = csg::kNone;
    s.background = {0.25, 0.5, 0.75};
    render::RenderOptions o;
    o.width = 8;
    o.height = 6;
    const render::Image im = render::render(s, o);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            CHECK(im.at(x, y, 0) == 0.25f);
            CHECK(im.at(x, y, 2) == 0.75f);
        }
}

TEST_CASE("rendering leaves the caller's floating-point mode alone", "[render]") {
    volatile double tiny = 1e-310;  // a denormal: flushed to 0 under FTZ/DAZ
    render::RenderOptions o;
    o.width = 8;
    o.height = 8;
    o.threads = 1;
    render::render(busy_scene(), o);
    volatile double half = tiny * 0.5;
    CHECK(half != 0.0);
}

TEST_CASE("rendering straight to 8-bit sRGB gives the bytes the float image encodes to", "[render][srgb8]") {
    // busy_scene: reflections, cut faces, a ground plane, two lights; spp 3
    // and a crop so jittered sums and tile borders are covered too.
    const csg::Scene s = busy_scene();
    for (const bool crop : {false, true}) {
        render::RenderOptions o;
        o.width = 70;
        o.height = 45;
        o.spp = 3;
        o.seed = 11;
        if (crop) o.crop = std::array<int, 4>{13, 5, 61, 44};
        const render::Image floats = render::render(s, o);
        o.srgb8 = true;
        const render::Image bytes = render::render(s, o);
        REQUIRE(bytes.pixels.empty());
        REQUIRE(bytes.srgb8.size() == floats.pixels.size());
        // The independent reference: the sRGB formula on the float image.
        int differ = 0, near_half = 0;
        for (std::size_t i = 0; i < floats.pixels.size(); ++i) {
            const double x = std::clamp(double(floats.pixels[i]), 0.0, 1.0);
            const double e = 255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055);
            if (long(bytes.srgb8[i]) == std::lround(e)) continue;
            ++differ;
            near_half += std::abs(e - std::floor(e) - 0.5) < 1e-4;  // float rounding at a half-way point
        }
        INFO((crop ? "crop" : "whole") << ": " << differ << " bytes differ from the formula");
        CHECK(differ == near_half);
        // And a colour image rendered as bytes writes only to 8-bit formats.
        CHECK(render::is_8bit_output("x.png"));
        CHECK_FALSE(render::is_8bit_output("x.EXR"));
        CHECK_THROWS_AS(render::write_image(bytes, "/tmp/never.exr"), render::ImageWriteError);
    }
}

// A plain render (1 spp, no adaptive AA, 8-bit) culls whole tiles and then
// 8×8 blocks of traced tiles whose rays all miss (render/tiles.hpp). A small
// sphere off-centre in a wide frame: a pixel shows the background exactly
// when its centre ray misses the sphere by the closed form (pixels within
// 1e-9 of its outline are skipped), and crops whose corners are not on
// any block border give the same bytes as the whole image.
TEST_CASE("culled blocks are background exactly where the centre rays miss", "[render][cull]") {
    csg::Scene s = make_scene(leaf(sphere(0.6, translate(0.9, 0.2, 0.4))));
    s.background = {0.2, 0.3, 0.4};
    s.camera.position = {2, -7, 3};
    s.lights.push_back(csg::Light{true, {}, {-1, 1, -2}, {1, 1, 1}, 1});
    render::RenderOptions o;
    o.width = 150;
    o.height = 110;
    o.srgb8 = true;
    const render::Image whole = render::render(s, o);
    REQUIRE(whole.srgb8.size() == std::size_t(150 * 110 * 3));
    const std::uint8_t* bg = &whole.srgb8[0];  // the corner: background
    const render::CameraModel camera(s.camera, o.width, o.height);
    const glm::dvec3 c(0.9, 0.2, 0.4);
    int hits = 0, misses = 0;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            glm::dvec3 ro, rd;
            REQUIRE(camera.ray(x + 0.5, y + 0.5, ro, rd));
            // The line's distance from the centre, against the radius.
            const glm::dvec3 w = c - ro;
            const double along = glm::dot(w, rd), miss = glm::length(w - along * rd) - 0.6;
            if (std::abs(miss) < 1e-9 || along <= 0) continue;
            const std::uint8_t* px = &whole.srgb8[(std::size_t(y) * o.width + x) * 3];
            const bool background = std::equal(px, px + 3, bg);
            INFO("pixel " << x << ", " << y << " passes " << miss << " from the sphere");
            CHECK(background == (miss > 0));
            (miss > 0 ? misses : hits)++;
        }
    CHECK(hits > 300);
    CHECK(misses > 10000);
    const std::array<int, 4> crops[] = {{3, 5, 77, 110}, {77, 0, 150, 61}, {77, 61, 150, 110}, {0, 0, 3, 110}, {3, 0, 77, 5}};
    for (const auto& cr : crops) {
        o.crop = cr;
        const render::Image part = render::render(s, o);
        for (int y = cr[1]; y < cr[3]; ++y)
            for (int x = cr[0]; x < cr[2]; ++x)
                for (int ch = 0; ch < 3; ++ch) {
                    INFO("crop pixel " << x << ", " << y);
                    REQUIRE(part.srgb8[(std::size_t(y - cr[1]) * part.width + (x - cr[0])) * 3 + ch] ==
                            whole.srgb8[(std::size_t(y) * o.width + x) * 3 + ch]);
                }
    }
    // Linear floats too (a culled block's rows are filled whole, render.cpp):
    // every pixel the 8-bit image shows as background holds the corner's floats.
    o.crop.reset();
    o.srgb8 = false;
    const render::Image linear = render::render(s, o);
    REQUIRE(linear.pixels.size() == std::size_t(150 * 110 * 3));
    int background = 0;
    for (std::size_t i = 0; i < std::size_t(150 * 110); ++i) {
        if (!std::equal(&whole.srgb8[3 * i], &whole.srgb8[3 * i] + 3, bg)) continue;
        ++background;
        INFO("pixel " << i);
        CHECK(std::equal(&linear.pixels[3 * i], &linear.pixels[3 * i] + 3, &linear.pixels[0]));
    }
    CHECK(background > 10000);
}

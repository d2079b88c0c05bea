// --alpha (RenderOptions::alpha): coverage of a sphere's silhouette read back
// from the PNG and EXR files against the circle's exact area in each pixel.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
namespace fs = std::filesystem;

namespace {

constexpr int kSide = 30;       // pixels; the view is 3 units high: 0.1 unit per pixel
constexpr double kRadius = 10;  // the unit sphere's silhouette, in pixels, centred at (15, 15)

// The share of pixel (x, y) inside the circle, by a 200×200 grid of points:
// the oracle knows nothing of the renderer's sample pattern.
double exact_coverage(int x, int y) {
    constexpr int n = 200;
    int inside = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double px = x + (i + 0.5) / n - 15, py = y + (j + 0.5) / n - 15;
            inside += px * px + py * py < kRadius * kRadius;
        }
    return double(inside) / (n * n);
}

csg::Scene sphere_scene() {
    csg::Scene s = make_scene(leaf(sphere(1)));
    s.camera.position = {0, -6, 0};
    s.camera.look_at = {0, 0, 0};
    s.camera.orthographic = true;
    s.camera.height = 3;
    s.background = {0.8, 0.1, 0.1};  // must not leak into the colour of covered pixels
    return s;
}

std::vector<float> write_and_read(const render::Image& im, const std::string& name, int& channels) {
    const fs::path file = fs::temp_directory_path() / ("kerf_alpha_" + std::to_string(::getpid()) + "_" + name);
    render::write_image(im, file.string());
    auto in = OIIO::ImageInput::open(file.string());
    REQUIRE(in);
    channels = in->spec().nchannels;
    REQUIRE(in->spec().alpha_channel == 3);
    std::vector<float> px(std::size_t(kSide) * kSide * channels);
    REQUIRE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, px.data()));
    in->close();
    fs::remove(file);
    return px;
}

}  // namespace

TEST_CASE("alpha is the silhouette's coverage: 0 on background, 1 inside, the area fraction on edges", "[render][alpha]") {
    render::RenderOptions o;
    o.width = o.height = kSide;
    o.spp = 64;
    o.alpha = render::Alpha::Straight;
    o.srgb8 = true;
    int c = 0;
    const std::vector<float> png = write_and_read(render::render(sphere_scene(), o), "a.png", c);
    REQUIRE(c == 4);
    int edges = 0;
    double worst = 0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const double exact = exact_coverage(x, y), a = png[(std::size_t(y) * kSide + x) * 4 + 3];
            if (exact == 0) REQUIRE(a == 0);
            else if (exact == 1) REQUIRE(a == 1);
            else ++edges, worst = std::max(worst, std::abs(a - exact));
        }
    CHECK(edges > 40);
    CHECK(worst < 0.1);  // 64 stratified samples (8×8): at most ~1/8 of a pixel off
}

TEST_CASE("adaptive anti-aliasing gives fractional alpha on edges too", "[render][alpha]") {
    render::RenderOptions o;
    o.width = o.height = kSide;
    o.adaptive = true;
    o.alpha = render::Alpha::Straight;
    const render::Image im = render::render(sphere_scene(), o);
    double err = 0;
    int edges = 0;
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const double exact = exact_coverage(x, y);
            if (exact > 0.05 && exact < 0.95) ++edges, err += std::abs(im.at(x, y, 3) - exact);
        }
    CHECK(err / edges < 0.1);
}

TEST_CASE("EXR alpha is premultiplied, PNG straight: no background in either colour", "[render][alpha]") {
    render::RenderOptions o;
    o.width = o.height = kSide;
    o.spp = 16;
    o.alpha = render::Alpha::Premultiplied;
    int c = 0;
    const std::vector<float> exr = write_and_read(render::render(sphere_scene(), o), "p.exr", c);
    o.alpha = render::Alpha::Straight;
    const render::Image straight = render::render(sphere_scene(), o);
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const std::size_t at = (std::size_t(y) * kSide + x) * 4;
            const float a = exr[at + 3];
            REQUIRE(a == Approx(straight.at(x, y, 3)));
            if (a == 0) REQUIRE((exr[at] == 0 && exr[at + 1] == 0 && exr[at + 2] == 0));
            for (int k = 0; k < 3; ++k) REQUIRE(exr[at + k] == Approx(straight.at(x, y, k) * a).margin(1e-5));
            // The sphere is grey-white: red would be the background leaking in.
            if (a > 0) REQUIRE(straight.at(x, y, 0) < straight.at(x, y, 1) * 1.2 + 1e-3);
        }
}

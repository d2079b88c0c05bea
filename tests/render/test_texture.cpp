// Image textures against the closed-form mappings (docs/language.md, "Image
// textures"): a test-written image of coloured quadrants is read back
// through OpenImageIO, then mapped planar onto a box seen head-on (each
// quadrant where u = x, v = y puts it, through the material frame and the
// pattern transform), spherically (the colour at a known longitude and
// latitude) and cylindrically; nearest against bilinear; the cache; errors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "csg/srgb.hpp"
#include "render/image/png_file.hpp"
#include "render/image/replace_file.hpp"
#include "render/render.hpp"
#include "render/texture.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::TextureMapping;

namespace {

// Writes a PNG of w × h pixels whose colour is colours[row * w + col] (8-bit sRGB codes).
std::string write_png(const std::string& name, int w, int h, const std::vector<glm::ivec3>& colours) {
    std::vector<std::uint8_t> px;
    for (const glm::ivec3& c : colours) px.insert(px.end(), {std::uint8_t(c.x), std::uint8_t(c.y), std::uint8_t(c.z)});
    std::vector<unsigned char> file;
    REQUIRE(render::encode_png(file, px.data(), w, h, 3, true).empty());
    const auto path = (std::filesystem::temp_directory_path() /
                       ("kerf_texture_" + std::to_string(::getpid()) + "_" + name)).string();
    REQUIRE(render::replace_file(path, file.data(), file.size()).empty());
    return path;
}

glm::dvec3 linear(const glm::ivec3& c) { return csg::srgb_to_linear(glm::dvec3(c) / 255.0); }

// Quadrants, top row first: red, green / blue, a mid grey (sRGB 128: not its own linear value).
const std::vector<glm::ivec3> kQuadrants = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {128, 128, 128}};

std::shared_ptr<const csg::Texture> read(const std::string& path) {
    std::string why;
    auto t = render::read_texture(path, why);
    INFO(why);
    REQUIRE(t);
    return t;
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-6) { return glm::length(a - b) <= eps; }

}  // namespace

TEST_CASE("a texture reads back as linear RGB, rows top first, once per file", "[render][texture]") {
    const std::string path = write_png("quad.png", 2, 2, kQuadrants);
    const auto t = read(path);
    REQUIRE(t->width == 2);
    REQUIRE(t->height == 2);
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 3; ++c) CHECK(t->rgb[i * 3 + c] == Approx(linear(kQuadrants[i])[c]).margin(1e-6));
    CHECK(read(path) == t);  // the cache: the same decoded image, not a second read
    std::string why;
    CHECK(render::read_texture(path + ".missing", why) == nullptr);
    CHECK(why.find("no such file") != std::string::npos);
    const std::string junk = write_png("junk.png", 1, 1, {{0, 0, 0}});
    REQUIRE(render::replace_file(junk, "not an image at all", 19).empty());
    why.clear();
    CHECK(render::read_texture(junk, why) == nullptr);
    CHECK(why.find("cannot read texture") != std::string::npos);
    std::filesystem::remove(path);
    std::filesystem::remove(junk);
}

TEST_CASE("EXR, TIFF, JPEG and PNG textures read back what was written", "[render][texture]") {
    // kerf writes them (render::write_image, its codec module), reads them
    // through the same module; OpenImageIO writes the second set (half-float
    // EXR, 8-bit and 16-bit TIFF and PNG), so the readers meet files they did not make.
    const std::string dir = std::filesystem::temp_directory_path() / ("kerf_texture_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    // 32×32 in 16×16 quadrants: JPEG's blocks see flat colour but at the
    // seams, so its quadrant centres keep their codes within a few steps.
    render::Image im;
    im.width = 32, im.height = 32, im.channels = 3, im.content = render::ImageContent::Color;
    auto quadrant = [](int x, int y) { return kQuadrants[(y / 16) * 2 + x / 16]; };
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (int k = 0; k < 3; ++k) im.pixels.push_back(float(linear(quadrant(x, y))[k]));
    for (const char* name : {"/q.exr", "/q.tif", "/q.jpg"}) {
        const std::string path = dir + name;
        render::write_image(im, path);
        const auto t = read(path);
        INFO(path);
        REQUIRE(t->width == 32);
        REQUIRE(t->height == 32);
        if (std::string(name) != "/q.jpg") {
            CHECK(std::equal(t->rgb.begin(), t->rgb.end(), im.pixels.begin(), im.pixels.end()));  // floats, exactly
            continue;
        }
        for (int y : {8, 24})
            for (int x : {8, 24})
                for (int k = 0; k < 3; ++k)
                    CHECK(csg::linear_to_srgb(t->rgb[(y * 32 + x) * 3 + k]) * 255 ==
                          Approx(quadrant(x, y)[k]).margin(3));
    }
    // PNG: 8-bit through kerf's own reader, 16-bit through OpenImageIO.
    for (const auto& [name, type] : {std::pair{"/o.exr", OIIO::TypeDesc::HALF}, std::pair{"/o8.tif", OIIO::TypeDesc::UINT8},
                                     std::pair{"/o16.tif", OIIO::TypeDesc::UINT16}, std::pair{"/o8.png", OIIO::TypeDesc::UINT8},
                                     std::pair{"/o16.png", OIIO::TypeDesc::UINT16}}) {
        const std::string path = dir + name;
        auto out = OIIO::ImageOutput::create(path);
        REQUIRE(out);
        const OIIO::ImageSpec spec(2, 2, 3, type);
        std::vector<float> px;  // sRGB-encoded values for integer files, linear for EXR
        for (const glm::ivec3& c : kQuadrants)
            for (int k = 0; k < 3; ++k) px.push_back(type == OIIO::TypeDesc::HALF ? float(linear(c)[k]) : c[k] / 255.0f);
        REQUIRE(out->open(path, spec));
        REQUIRE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        REQUIRE(out->close());
        const auto t = read(path);
        INFO(path);
        REQUIRE(t->width == 2);
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k)
                CHECK(t->rgb[i * 3 + k] == Approx(linear(kQuadrants[i])[k]).margin(type == OIIO::TypeDesc::HALF ? 1e-3 : 1e-6));
    }
    std::filesystem::remove_all(dir);
}

TEST_CASE("planar: u = x, v = y, the image over the unit square, repeated", "[render][texture]") {
    const auto t = read(write_png("planar.png", 2, 2, kQuadrants));
    auto at = [&](double x, double y, bool bilinear) {
        return render::texture_color(*t, TextureMapping::Planar, bilinear, render::texture_uv(TextureMapping::Planar, {x, y, 7}));
    };
    for (bool bilinear : {false, true}) {
        // Pixel centres: both filters give the pixel's own colour.
        CHECK(near(at(0.25, 0.75, bilinear), linear(kQuadrants[0])));
        CHECK(near(at(0.75, 0.75, bilinear), linear(kQuadrants[1])));
        CHECK(near(at(0.25, 0.25, bilinear), linear(kQuadrants[2])));
        CHECK(near(at(0.75, 0.25, bilinear), linear(kQuadrants[3])));
        CHECK(near(at(-0.75, 3.25, bilinear), linear(kQuadrants[2])));  // repeated
    }
    // Off centre the nearest pixel is its cell's, bilinear blends the centres.
    CHECK(near(at(0.05, 0.95, false), linear(kQuadrants[0])));
    CHECK(near(at(0.5, 0.75, true), 0.5 * (linear(kQuadrants[0]) + linear(kQuadrants[1]))));
    CHECK(near(at(0.5, 0.5, true), 0.25 * (linear(kQuadrants[0]) + linear(kQuadrants[1]) + linear(kQuadrants[2]) +
                                           linear(kQuadrants[3]))));
    // Across the repeat seam bilinear blends the last column with the first.
    CHECK(near(at(1.0, 0.75, true), 0.5 * (linear(kQuadrants[0]) + linear(kQuadrants[1]))));
}

TEST_CASE("spherical and cylindrical: the colour at a known longitude and latitude", "[render][texture]") {
    // 4 columns (longitude quarters from +x counter-clockwise) × 2 rows (north, south).
    std::vector<glm::ivec3> c;
    for (int i = 0; i < 8; ++i) c.push_back({30 * i, 255 - 30 * i, (i * 97) % 256});
    const auto t = read(write_png("sphere.png", 4, 2, c));
    using std::numbers::pi;
    auto dir = [](double lon, double lat, double r) {
        return r * glm::dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    };
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 2; ++row) {
            // The pixel centre: longitude (col + ½)·90°, latitude ±45°.
            const double lon = (col + 0.5) * pi / 2, lat = row == 0 ? pi / 4 : -pi / 4;
            INFO(col << " " << row);
            const glm::dvec2 uv = render::texture_uv(TextureMapping::Spherical, dir(lon, lat, 3.7));
            CHECK(uv.x == Approx((col + 0.5) / 4));
            CHECK(uv.y == Approx(row == 0 ? 0.75 : 0.25));
            CHECK(near(render::texture_color(*t, TextureMapping::Spherical, true, uv), linear(c[row * 4 + col]), 1e-5));
            // Anywhere inside the pixel's cell, nearest gives the same colour.
            const glm::dvec2 off = render::texture_uv(TextureMapping::Spherical, dir(lon + 0.6, lat * 0.3 + (row ? -1.2 : 1.2) * 0.5, 1));
            CHECK(near(render::texture_color(*t, TextureMapping::Spherical, false, off), linear(c[row * 4 + col])));
            // Cylindrical: the same longitude, height z in [0, 1) per image, repeated.
            const glm::dvec3 q{std::cos(lon), std::sin(lon), row == 0 ? 2.75 : -0.75};
            CHECK(near(render::texture_color(*t, TextureMapping::Cylindrical, true, render::texture_uv(TextureMapping::Cylindrical, q)),
                       linear(c[row * 4 + col]), 1e-5));
        }
    // The poles clamp to their row instead of wrapping to the other pole.
    CHECK(near(render::texture_color(*t, TextureMapping::Spherical, true, render::texture_uv(TextureMapping::Spherical, {0, 0, 1})),
               render::texture_color(*t, TextureMapping::Spherical, true, {0.0, 0.75}), 1e-5));
}

TEST_CASE("planar texture on a box seen head-on: each quadrant where the mapping puts it", "[render][texture]") {
    // The box spans x ∈ [3, 5], y ∈ [0, 2]; its material() call was at x = 3
    // (its material frame moves by −3) and pattern_scale 2 halves pattern
    // space, so u = (x − 3)/2, v = y/2 on the top face.
    csg::Material m;
    m.pattern = csg::Pattern::Image;
    m.texture = read(write_png("box.png", 2, 2, kQuadrants));
    m.bilinear = false;
    m.specular = 0;
    m.pattern_from_material.linear = glm::dmat3(0.5);
    csg::Leaf l = box({3, 0, -1}, {5, 2, 0});
    csg::Scene s = make_scene(leaf(l), {m});
    csg::Affine frame;
    frame.offset = {-3, 0, 0};
    s.material_frames.push_back(frame);
    s.leaves.at(0).material_frame = 1;
    s.lights.clear();  // colour = ambient 0.1 × albedo, nothing else
    s.background = glm::dvec3(0.5, 0.25, 0.125);
    look_down(s, {4, 1, 0}, 10, 2);
    render::RenderOptions o;
    o.width = o.height = 8;
    o.threads = 1;
    const render::Image img = render::render(s, o);
    for (int py = 0; py < 8; ++py)
        for (int px = 0; px < 8; ++px) {
            // The pixel centre's world point and its quadrant by the closed form.
            const double x = 3 + (px + 0.5) / 4, y = 2 - (py + 0.5) / 4;
            const double u = (x - 3) / 2, v = y / 2;
            const int quadrant = (v < 0.5 ? 2 : 0) + (u < 0.5 ? 0 : 1);
            const glm::dvec3 want = 0.1 * linear(kQuadrants[quadrant]);
            INFO(px << " " << py);
            for (int c = 0; c < 3; ++c) CHECK(img.at(px, py, c) == Approx(want[c]).margin(1e-5));
        }
}

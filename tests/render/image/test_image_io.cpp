// write_image: formats, encodings, atomic replacement, errors.
#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "render/render.hpp"

using namespace kerf;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("kerf_image_io_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

render::Image gradient(int channels, render::ImageContent content) {
    render::Image im;
    im.width = 4;
    im.height = 3;
    im.channels = channels;
    im.content = content;
    for (int i = 0; i < 4 * 3 * channels; ++i) im.pixels.push_back(float(i) / (4 * 3 * channels));
    return im;
}

std::vector<float> read_back(const fs::path& p, int& w, int& h, int& c, OIIO::TypeDesc& stored) {
    auto in = OIIO::ImageInput::open(p.string());
    REQUIRE(in);
    const OIIO::ImageSpec& spec = in->spec();
    w = spec.width, h = spec.height, c = spec.nchannels;
    stored = spec.format;
    std::vector<float> px(std::size_t(w) * h * c);
    REQUIRE(in->read_image(0, 0, 0, c, OIIO::TypeDesc::FLOAT, px.data()));
    in->close();
    return px;
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), {}};
}

}  // namespace

TEST_CASE("PNG is 8-bit sRGB-encoded", "[image_io]") {
    const fs::path dir = fresh_dir("png");
    render::Image im = gradient(3, render::ImageContent::Color);
    im.pixels[0] = 0.5f;  // linear 0.5 is sRGB 0.7354 -> 188/255
    im.pixels[1] = 0.0f;
    im.pixels[2] = 1.0f;
    render::write_image(im, (dir / "a.png").string());
    int w, h, c;
    OIIO::TypeDesc t;
    const auto px = read_back(dir / "a.png", w, h, c, t);
    CHECK(w == 4);
    CHECK(h == 3);
    CHECK(c == 3);
    CHECK(t == OIIO::TypeDesc::UINT8);
    CHECK(std::lround(px[0] * 255) == 188);
    CHECK(px[1] == 0.0f);
    CHECK(px[2] == 1.0f);
    fs::remove_all(dir);
}

TEST_CASE("PNG image data compressed in parallel bands reads back exactly", "[image_io]") {
    // 261 rows: 16 full pieces of 16 rows (png_pieces.hpp) and a partial
    // one; noisy content (nothing for run-length matching to hide) beside
    // flat runs.
    const fs::path dir = fresh_dir("png_bands");
    for (const int channels : {1, 3}) {
        render::Image im;
        im.width = 301;
        im.height = 261;
        im.channels = channels;
        im.content = channels == 1 ? render::ImageContent::Hits : render::ImageContent::Normal;
        std::uint32_t state = 12345;
        for (int i = 0; i < im.width * im.height * channels; ++i) {
            state = state * 1664525u + 1013904223u;
            const bool flat = (i / (im.width * channels)) % 7 == 3;  // every 7th row constant
            im.pixels.push_back(flat ? 0.25f : float(state >> 8) / float(1u << 24));
        }
        if (channels == 1) im.pixels[0] = 1.0f;  // hits are scaled by the largest value
        const fs::path file = dir / ("bands" + std::to_string(channels) + ".png");
        render::write_image(im, file.string());
        int w, h, c;
        OIIO::TypeDesc t;
        const auto px = read_back(file, w, h, c, t);
        REQUIRE(w == im.width);
        REQUIRE(h == im.height);
        REQUIRE(c == channels);
        int wrong = 0;
        for (std::size_t i = 0; i < px.size(); ++i) {
            const float v = channels == 1 ? im.pixels[i] : 0.5f * im.pixels[i] + 0.5f;
            const long want = long(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
            wrong += std::lround(px[i] * 255) != want;
        }
        CHECK(wrong == 0);
    }
    fs::remove_all(dir);
}

TEST_CASE("PNG colour bytes are round(255 * sRGB(linear)) over the whole range", "[image_io]") {
    const fs::path dir = fresh_dir("png_ramp");
    render::Image im;
    im.width = 4099;
    im.height = 1;
    im.channels = 3;
    im.content = render::ImageContent::Color;
    std::vector<double> linear;
    for (int i = 0; i < 4096 * 3; ++i) linear.push_back(std::pow(i / (4096.0 * 3 - 1), 2.2));  // dense in the darks
    for (double v : {-1.0, 2.0, 1e30, -0.0, 0.0031308, 1e-9, 0.5, 0.999, 1.0}) linear.push_back(v);
    for (double v : linear) im.pixels.push_back(float(v));
    render::write_image(im, (dir / "ramp.png").string());
    int w, h, c;
    OIIO::TypeDesc t;
    const auto px = read_back(dir / "ramp.png", w, h, c, t);
    REQUIRE(px.size() == linear.size());
    int off_by_one = 0;
    for (std::size_t i = 0; i < linear.size(); ++i) {
        const double x = std::clamp(double(float(linear[i])), 0.0, 1.0);
        const double e = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
        const double exact = 255 * e;
        const long got = std::lround(px[i] * 255);
        if (got == std::lround(exact)) continue;
        // Only a value within float rounding of a half-way point may round either way.
        INFO("linear " << linear[i] << " exact " << exact << " got " << got);
        CHECK(std::abs(exact - std::floor(exact) - 0.5) < 1e-4);
        ++off_by_one;
    }
    CHECK(off_by_one < 3);
    fs::remove_all(dir);
}

TEST_CASE("EXR and TIFF keep linear floats, +inf included", "[image_io]") {
    const fs::path dir = fresh_dir("exr");
    render::Image im = gradient(1, render::ImageContent::Depth);
    im.pixels[5] = std::numeric_limits<float>::infinity();
    for (const char* name : {"d.exr", "d.tif"}) {
        render::write_image(im, (dir / name).string());
        int w, h, c;
        OIIO::TypeDesc t;
        const auto px = read_back(dir / name, w, h, c, t);
        REQUIRE(px.size() == im.pixels.size());
        CHECK(t == OIIO::TypeDesc::FLOAT);
        CHECK(std::isinf(px[5]));
        for (std::size_t i = 0; i < px.size(); ++i)
            if (i != 5) CHECK(px[i] == im.pixels[i]);
    }
    fs::remove_all(dir);
}

TEST_CASE("EXR and TIFF keep RGB and premultiplied RGBA floats exactly", "[image_io]") {
    // Written by kerf's own codecs (OpenEXR, libtiff), read back by
    // OpenImageIO: the independent side.
    const fs::path dir = fresh_dir("rgba");
    for (int channels : {3, 4}) {
        const render::Image im = gradient(channels, render::ImageContent::Color);
        for (const char* ext : {".exr", ".tif", ".tiff", ".EXR"}) {
            const fs::path file = dir / ("c" + std::to_string(channels) + ext);
            render::write_image(im, file.string());
            int w, h, c;
            OIIO::TypeDesc t;
            const auto px = read_back(file, w, h, c, t);
            INFO(file);
            CHECK(w == 4);
            CHECK(h == 3);
            CHECK(c == channels);
            CHECK(t == OIIO::TypeDesc::FLOAT);
            CHECK(std::equal(px.begin(), px.end(), im.pixels.begin(), im.pixels.end()));
        }
    }
    fs::remove_all(dir);
}

TEST_CASE("JPEG is 8-bit sRGB-encoded, within the codec's loss", "[image_io]") {
    // A 32×24 colour ramp: JPEG at quality 98 keeps every code within
    // a few steps (chroma is subsampled); read back by OpenImageIO.
    const fs::path dir = fresh_dir("jpeg");
    render::Image im;
    im.width = 32, im.height = 24, im.channels = 3, im.content = render::ImageContent::Color;
    // Smooth in the stored codes: linear values of an sRGB ramp.
    auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x)
            im.pixels.insert(im.pixels.end(), {float(linear(x / 31.0)), float(linear(y / 23.0)), 0.5f});
    auto srgb = [](double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; };
    for (const char* name : {"a.jpg", "a.jpeg"}) {
        render::write_image(im, (dir / name).string());
        CHECK(slurp(dir / name).substr(0, 3) == "\xFF\xD8\xFF");  // a JPEG stream
        int w, h, c;
        OIIO::TypeDesc t;
        const auto px = read_back(dir / name, w, h, c, t);
        CHECK(w == 32);
        CHECK(h == 24);
        REQUIRE(c == 3);
        CHECK(t == OIIO::TypeDesc::UINT8);
        double worst = 0, sum = 0;
        for (std::size_t i = 0; i < px.size(); ++i) {
            const double d = std::abs(px[i] * 255 - std::round(255 * srgb(im.pixels[i])));
            worst = std::max(worst, d);
            sum += d;
        }
        CHECK(worst <= 8);
        CHECK(sum / double(px.size()) < 1.5);
    }
    fs::remove_all(dir);
}

TEST_CASE("PFM keeps linear floats, +inf included, and reads back through OpenImageIO", "[image_io]") {
    // kerf writes PFM itself; OpenImageIO's reader (the independent side)
    // undoes the bottom-up row order and the byte order.
    const fs::path dir = fresh_dir("pfm");
    for (int channels : {1, 3}) {
        render::Image im = gradient(channels, channels == 1 ? render::ImageContent::Depth : render::ImageContent::Color);
        im.pixels[2] = std::numeric_limits<float>::infinity();
        const fs::path file = dir / ("x" + std::to_string(channels) + ".pfm");
        render::write_image(im, file.string());
        CHECK(slurp(file).substr(0, 2) == (channels == 1 ? "Pf" : "PF"));
        int w, h, c;
        OIIO::TypeDesc t;
        const auto px = read_back(file, w, h, c, t);
        CHECK(w == 4);
        CHECK(h == 3);
        CHECK(c == channels);
        REQUIRE(px.size() == im.pixels.size());
        CHECK(std::isinf(px[2]));
        for (std::size_t i = 0; i < px.size(); ++i)
            if (i != 2) CHECK(px[i] == im.pixels[i]);
    }
    fs::remove_all(dir);
}

TEST_CASE("PGM is grey: a colour image is written as its luminance", "[image_io]") {
    const fs::path dir = fresh_dir("pgm");
    render::Image im = gradient(3, render::ImageContent::Color);
    render::write_image(im, (dir / "c.pgm").string());
    CHECK(slurp(dir / "c.pgm").substr(0, 2) == "P5");
    int w, h, c;
    OIIO::TypeDesc t;
    const auto px = read_back(dir / "c.pgm", w, h, c, t);
    REQUIRE(c == 1);
    REQUIRE(px.size() == 12);
    auto srgb = [](double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055; };
    for (std::size_t i = 0; i < 12; ++i) {
        const float* p = &im.pixels[3 * i];
        const double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        CHECK(px[i] * 255 == Approx(std::round(255 * srgb(y))).margin(0.01));
    }
    // The same from an image rendered straight into sRGB bytes.
    render::Image bytes;
    bytes.width = 2, bytes.height = 1, bytes.channels = 3;
    bytes.srgb8 = {255, 255, 255, 0, 255, 0};
    render::write_image(bytes, (dir / "b.pgm").string());
    const auto pb = read_back(dir / "b.pgm", w, h, c, t);
    REQUIRE(pb.size() == 2);
    CHECK(pb[0] == 1.0f);
    CHECK(pb[1] * 255 == Approx(std::round(255 * srgb(0.7152))).margin(0.01));
    fs::remove_all(dir);
}

TEST_CASE("8-bit depth is normalised: nearest white, misses black", "[image_io]") {
    const fs::path dir = fresh_dir("depth8");
    render::Image im = gradient(1, render::ImageContent::Depth);
    im.pixels[0] = std::numeric_limits<float>::infinity();
    render::write_image(im, (dir / "d.png").string());
    int w, h, c;
    OIIO::TypeDesc t;
    const auto px = read_back(dir / "d.png", w, h, c, t);
    CHECK(px[0] == 0.0f);  // miss
    CHECK(px[1] == 1.0f);  // nearest hit
    CHECK(px[11] > 0.1f);  // farthest hit: still distinguishable from a miss
    CHECK(px[11] < px[1]);
    fs::remove_all(dir);
}

TEST_CASE("a failed write leaves the old file intact and no temporary behind", "[image_io]") {
    const fs::path dir = fresh_dir("atomic");
    const fs::path target = dir / "out.png";
    render::write_image(gradient(3, render::ImageContent::Color), target.string());
    const std::string before = slurp(target);
    REQUIRE(!before.empty());
    // PNG cannot hold 7 channels: the writer fails after the file was chosen.
    render::Image bad = gradient(7, render::ImageContent::Color);
    CHECK_THROWS_AS(render::write_image(bad, target.string()), render::ImageWriteError);
    CHECK(slurp(target) == before);
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
    CHECK(files == 1);
    fs::remove_all(dir);
}

TEST_CASE("writing to a missing folder or an unknown format throws a one-line error", "[image_io]") {
    const fs::path dir = fresh_dir("missing");
    try {
        render::write_image(gradient(3, render::ImageContent::Color), (dir / "no" / "such" / "x.png").string());
        FAIL("no exception");
    } catch (const render::ImageWriteError& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
        CHECK(std::string(e.what()).find("x.png") != std::string::npos);
    }
    CHECK_THROWS_AS(render::write_image(gradient(3, render::ImageContent::Color), (dir / "x.nosuchformat").string()),
                    render::ImageWriteError);
    fs::remove_all(dir);
}

TEST_CASE("JPEG 2000 is refused below 32 pixels each way, and reads back from 32", "[image_io]") {
    // OpenJPEG's writer reported success below 32 pixels over a 77-byte file
    // that reads back as nothing.
    const fs::path dir = fresh_dir("jp2");
    const auto sized = [](int w, int h) {
        render::Image im;
        im.width = w, im.height = h, im.channels = 3;
        for (int i = 0; i < w * h * 3; ++i) im.pixels.push_back(float(i % 7) / 7);
        return im;
    };
    for (const auto& [w, h] : {std::pair{31, 32}, std::pair{32, 31}, std::pair{1, 1}}) {
        INFO(w << "x" << h);
        CHECK_THROWS_WITH(render::write_image(sized(w, h), (dir / "small.jp2").string()),
                          Catch::Contains("JPEG 2000 needs at least 32x32 pixels"));
        CHECK_FALSE(fs::exists(dir / "small.jp2"));
    }
    for (const char* name : {"ok.jp2", "ok.j2k"}) {
        render::write_image(sized(32, 40), (dir / name).string());
        int w, h, c;
        OIIO::TypeDesc t;
        const auto px = read_back(dir / name, w, h, c, t);
        CHECK(w == 32);
        CHECK(h == 40);
        CHECK(c == 3);
    }
    fs::remove_all(dir);
}

TEST_CASE("formats whose writer opens the file itself are encoded in memory too", "[image_io]") {
    // SGI's writer has no IOProxy: it writes to a memory file, and kerf
    // writes the bytes.
    const fs::path dir = fresh_dir("sgi");
    render::Image im = gradient(3, render::ImageContent::Normal);
    render::write_image(im, (dir / "n.sgi").string());
    int w, h, c;
    OIIO::TypeDesc t;
    const auto px = read_back(dir / "n.sgi", w, h, c, t);
    REQUIRE(px.size() == im.pixels.size());
    for (std::size_t i = 0; i < px.size(); ++i)
        CHECK(std::lround(px[i] * 255) == std::lround(std::clamp(0.5f * im.pixels[i] + 0.5f, 0.0f, 1.0f) * 255));
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
    CHECK(files == 1);
    fs::remove_all(dir);
}

// The CLI frees the scene from write_image's `on_encoded`, meant to run
// while the file is written and synced: for a PNG once, before the file
// exists; for other formats once, after it is written.
TEST_CASE("write_image calls on_encoded once: before a PNG is written, after other formats", "[image_io]") {
    const fs::path dir = fresh_dir("on_encoded");
    const render::Image im = gradient(3, render::ImageContent::Color);
    for (const char* name : {"a.png", "a.pfm", "a.ppm"}) {
        const fs::path target = dir / name;
        const bool png = std::string(name) == "a.png";
        int calls = 0;
        bool existed = false;
        render::write_image(im, target.string(), {}, -1, [&] {
            ++calls;
            existed = fs::exists(target);
        });
        CAPTURE(name);
        CHECK(calls == 1);
        CHECK(existed == !png);
        CHECK(fs::exists(target));
    }
}

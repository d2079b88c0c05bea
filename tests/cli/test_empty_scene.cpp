// A scene with no solid (docs/openscad.md, "An empty model"): render writes
// the background and warns, exit 0 (--werror: exit 1, no file); check and
// dump stay silent, as OpenSCAD's echo export does. OpenSCAD 2021.01 writes
// the same background PNG silently and refuses an STL with "Current top
// level object is empty.".
#include <catch2/catch.hpp>

#include <cmath>

#include "render/image/png_read.hpp"
#include "tests/cli/run_kerf.hpp"

namespace fs = std::filesystem;

TEST_CASE("render of an empty model writes its background and warns") {
    auto dir = test_dir("empty_scene");
    // Old/example023.scad without Debian's MCAD: the library is missing,
    // so every polygon is undef and nothing is made.
    const std::string scad = write_file(dir / "empty.scad",
                                        "use <no_such_fonts.scad>\n"
                                        "font = polyfont();\n"
                                        "linear_extrude(2) polygon(points = font[0]);\n");
    const std::string warned = scad + ": warning: the scene has no solid: the image is only its background";
    const fs::path png = dir / "empty.png";

    auto r = run_kerf("render --no-progress -W 6 -H 4 '" + scad + "' -o '" + png.string() + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find(scad + ":1:1: warning: Can't open library 'no_such_fonts.scad'.") != std::string::npos);
    CHECK(r.err.find(warned) != std::string::npos);
    kerf::render::PngPicture p;
    REQUIRE(kerf::render::read_png(png.string(), p).empty());
    REQUIRE(p.width == 6);
    REQUIRE(p.height == 4);
    // The studio look's background (no lights in the script), linear 0.5
    // grey (docs/language.md, "The default look"), in sRGB: no ground is
    // drawn under nothing.
    const double srgb = 255 * (1.055 * std::pow(0.5, 1 / 2.4) - 0.055);
    for (std::uint8_t v : p.pixels) CHECK(std::abs(v - srgb) <= 1);

    // --look plain: the dark grey of docs/spec.md §6.
    r = run_kerf("render --no-progress --look plain -W 6 -H 4 '" + scad + "' -o '" + png.string() + "'", dir);
    CHECK(r.status == 0);
    REQUIRE(kerf::render::read_png(png.string(), p).empty());
    const double plain = 255 * (1.055 * std::pow(0.2, 1 / 2.4) - 0.055);
    for (std::uint8_t v : p.pixels) CHECK(std::abs(v - plain) <= 1);

    for (const char* cmd : {"check", "dump"}) {
        r = run_kerf(std::string(cmd) + " '" + scad + "'", dir);
        CHECK(r.status == 0);
        CHECK(r.err.find("no solid") == std::string::npos);
    }
    // A script that draws a solid does not warn.
    const std::string cube = write_file(dir / "cube.sdl", "cube(1);\n");
    r = run_kerf("render --no-progress -W 6 -H 4 '" + cube + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
}

TEST_CASE("an empty model's render fails under --werror, writing nothing") {
    auto dir = test_dir("empty_scene_werror");
    const std::string sdl = write_file(dir / "nothing.sdl", "x = 1;\n");
    const fs::path png = dir / "nothing.png";
    auto r = run_kerf("render --werror --no-progress -W 6 -H 4 '" + sdl + "' -o '" + png.string() + "'", dir);
    CHECK(r.status == 1);
    CHECK(r.err.find(sdl + ": error: the scene has no solid: the image is only its background [--werror]") !=
          std::string::npos);
    CHECK_FALSE(fs::exists(png));
}

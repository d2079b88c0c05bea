// The `%` and `#` ghosts through the real binary (docs/openscad.md,
// "Modifiers"): drawn by default, gone with --no-ghosts; never measured
// (`kerf measure` agrees with OpenSCAD's STL, which leaves `%` parts out);
// a model of ghosts only says so.
#include <catch2/catch.hpp>

#include "render/image/png_read.hpp"
#include "tests/cli/measure_scene.hpp"

TEST_CASE("ghosts are drawn unless --no-ghosts, and only the solid is measured") {
    auto dir = test_dir("ghosts_option");
    const std::string text = "$fn = 64;\nsphere(1);\n%translate([3, 0, 0]) cube(2, center = true);\n#cylinder(r = 0.5, h = 3);";
    // The sphere and the cylinder's part above it (the cylinder less the
    // solid of revolution under the sphere's cap), without the % cube.
    const Measured m = measure(dir, text);
    const double sphere = 4.0 / 3 * M_PI;
    const double cylinder_out = M_PI * 0.25 * 3 - 2 * M_PI / 3 * (1 - std::pow(0.75, 1.5));
    check_volume(m, sphere + cylinder_out, 1e-2);  // faceted or exact, as --facets auto decides
    const double stl = openscad_volume(dir, text);
    if (std::isfinite(stl)) CHECK(std::abs(m.volume - stl) < 0.02 * stl);  // OpenSCAD's facets: 2 %
    CHECK(run_kerf("measure --no-ghosts '" + (dir / "scene.scad").string() + "'", dir).status == 2);  // an image option

    // Ghosts only: a picture of them, with the warning that there is no solid.
    const std::string ghost = write_file(dir / "ghost.scad", "%cube(2);\n");
    const std::string png = (dir / "ghost.png").string();
    auto r = run_kerf("render --no-progress -W 40 -H 30 '" + ghost + "' -o '" + png + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find("the scene has no solid: the image is only its background and its ghosts") != std::string::npos);
    kerf::render::PngPicture with, without;
    REQUIRE(kerf::render::read_png(png, with).empty());
    r = run_kerf("render --no-progress --no-ghosts -W 40 -H 30 '" + ghost + "' -o '" + png + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find("the image is only its background\n") != std::string::npos);
    REQUIRE(kerf::render::read_png(png, without).empty());
    REQUIRE(with.pixels.size() == without.pixels.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < with.pixels.size(); ++i) differ += with.pixels[i] != without.pixels[i];
    CHECK(differ > 300);  // the framed ghost covers much of the image
    for (std::uint8_t v : without.pixels) CHECK(v == without.pixels[0]);  // the background alone
}

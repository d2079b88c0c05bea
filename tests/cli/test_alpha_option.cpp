// --alpha on the command line: a format without an alpha channel is a usage
// error (exit 2), never an image with the coverage silently dropped.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

TEST_CASE("alpha output refuses formats without an alpha channel and AOVs") {
    auto dir = test_dir("alpha_option");
    const struct {
        const char* args;
        const char* error;
    } cases[] = {
        {"-o x.ppm --alpha", "--alpha needs an output format with an alpha channel (.png, .exr, .tif), not '.ppm'"},
        {"-o x.pgm --alpha", "--alpha needs an output format with an alpha channel (.png, .exr, .tif), not '.pgm'"},
        {"-o x.JPG --alpha", "--alpha needs an output format with an alpha channel (.png, .exr, .tif), not '.jpg'"},
        {"-o x.png --alpha --aov depth", "--alpha applies to the shaded image, not to --aov"},
    };
    for (const auto& c : cases) {
        const auto r = run_kerf(std::string("render x.sdl ") + c.args, dir);
        INFO(c.args);
        CHECK(r.status == 2);
        CHECK(first_line(r.err) == std::string("kerf: error: ") + c.error);
    }
}

TEST_CASE("alpha output writes a 4-channel PNG whose corner is transparent") {
    auto dir = test_dir("alpha_png");
    write_file(dir / "s.sdl", "camera(position = [0, -6, 0], look_at = [0, 0, 0]);\nsphere(1);\n");
    const std::string d = "'" + dir.string() + "/";
    const auto r = run_kerf("render " + d + "s.sdl' -o " + d + "a.png' -W 32 -H 32 --alpha", dir);
    REQUIRE(r.status == 0);
    std::ifstream f(dir / "a.png", std::ios::binary);
    const std::string png((std::istreambuf_iterator<char>(f)), {});
    REQUIRE(png.size() > 26);
    CHECK(int(png[25]) == 6);  // IHDR colour type 6: RGB + alpha
}

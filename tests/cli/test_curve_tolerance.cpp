// --curve-tolerance reaches text(): a coarse tolerance draws visibly other
// glyphs than a fine one, a value out of its range is a usage error.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

TEST_CASE("the curve tolerance option is checked and changes the flattened glyphs") {
    auto dir = test_dir("curve_tolerance");
    for (const char* bad : {"0", "-1e-4", "0.5", "nan", "abc"}) {
        const auto r = run_kerf(std::string("render x.sdl --curve-tolerance ") + bad, dir);
        INFO(bad);
        CHECK(r.status == 2);
        CHECK(first_line(r.err) == std::string("kerf: error: --curve-tolerance expects a number from 1e-9 to 0.1, got '") +
                                       bad + "'");
    }
    write_file(dir / "o.sdl",
               "camera(position = [4, -3, 30], look_at = [4, 4, 0]);\nlinear_extrude(1) text(\"O\", size = 10);\n");
    const std::string d = "'" + dir.string() + "/";
    auto render = [&](const char* tol, const char* out) {
        const auto r = run_kerf("render " + d + "o.sdl' -o " + d + out + "' -W 96 -H 96 --aa off --curve-tolerance " + tol, dir);
        REQUIRE(r.status == 0);
        return slurp(dir / out);
    };
    const std::string coarse = render("0.1", "coarse.ppm"), fine = render("1e-6", "fine.ppm"),
                      fine2 = render("1e-6", "fine2.ppm");
    CHECK(coarse != fine);
    CHECK(fine == fine2);
}

// kerf measure through the real binary: its four lines, its option rules and
// its exit statuses (docs/spec.md §15).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "tests/cli/run_kerf.hpp"

namespace {

// The number after `key: ` on its line of `out` (NaN if absent).
double figure(const std::string& out, const std::string& key, std::size_t skip = 0) {
    std::size_t at = out.find(key + ": ");
    if (at == std::string::npos) return std::nan("");
    at += key.size() + 2;
    for (std::size_t k = 0; k < skip; ++k) at = out.find_first_of(",±", at) + 1;
    while (at < out.size() && (out[at] == '[' || out[at] == ' ' || out[at] == '\x80' || out[at] == '\xb1' || out[at] == '\xc2')) ++at;
    return std::strtod(out.c_str() + at, nullptr);
}

}  // namespace

TEST_CASE("kerf measure prints the volume, area, centroid and bounds of a box") {
    auto dir = test_dir("measure_box");
    const std::string scene = write_file(dir / "part.sdl", "translate([1, 2, 3]) cube([2, 3, 4]);\n");
    auto r = run_kerf("measure '" + scene + "' --resolution 64 --threads 1", dir);
    REQUIRE(r.status == 0);
    INFO(r.out);
    CHECK(r.out.find("volume: ") == 0);
    CHECK(figure(r.out, "volume") == Approx(24).epsilon(1e-6));
    CHECK(figure(r.out, "area") == Approx(52).epsilon(1e-6));
    CHECK(figure(r.out, "centroid", 0) == Approx(2));
    CHECK(figure(r.out, "centroid", 1) == Approx(3.5));
    CHECK(figure(r.out, "centroid", 2) == Approx(5));
    CHECK(r.out.find("bounds: [[1, 2, 3], [3, 5, 7]]") != std::string::npos);
}

TEST_CASE("kerf measure of a sphere agrees with 4/3 pi r^3 within its error") {
    auto dir = test_dir("measure_sphere");
    const std::string scene = write_file(dir / "ball.sdl", "sphere(r = 2);\n");
    auto r = run_kerf("measure '" + scene + "'", dir);
    REQUIRE(r.status == 0);
    const double exact = 4.0 / 3.0 * M_PI * 8;
    CHECK(std::abs(figure(r.out, "volume") - exact) <= figure(r.out, "volume", 1));
    CHECK(std::abs(figure(r.out, "area") - 16 * M_PI) <= figure(r.out, "area", 1));
}

TEST_CASE("kerf measure refuses image options and bad resolutions, and an unbounded solid") {
    auto dir = test_dir("measure_bad");
    const std::string scene = write_file(dir / "part.sdl", "cube(1);\n");
    for (const char* bad : {"-o x.png", "-W 100", "--spp 4", "--resolution 9", "--resolution 4", "--aov depth"}) {
        auto r = run_kerf("measure '" + scene + "' " + bad, dir);
        INFO(bad << ": " << r.err);
        CHECK(r.status == 2);
        CHECK(r.err.find("kerf: error: ") == 0);
    }
    const std::string plane = write_file(dir / "plane.sdl", "plane([0, 0, 1], 0);\n");
    auto r = run_kerf("measure '" + plane + "'", dir);
    CHECK(r.status == 1);
    CHECK(r.err.find("unbounded") != std::string::npos);
    const std::string none = write_file(dir / "none.sdl", "x = 1;\n");
    r = run_kerf("measure '" + none + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.out.find("volume: 0 ± 0") == 0);
    CHECK(r.err.find("warning") != std::string::npos);
}

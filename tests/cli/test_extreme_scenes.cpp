// Valid scenes at the numbers' extremes that the fuzzer found hanging or
// aborting: each renders, exit 0, within a bounded time (run_kerf_bounded:
// a hang is the timeout's 124, an abort a signal).
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

namespace {

void renders(const std::string& name, const std::string& text) {
    const auto dir = test_dir("extreme_" + name);
    const std::string scene = write_file(dir / (name + ".sdl"), text);
    const auto png = dir / (name + ".png");
    const KerfRun r = run_kerf_bounded("render --no-progress -W 64 -H 48 '" + scene + "' -o '" + png.string() + "'", dir, 30);
    INFO(text << "\nstderr: " << r.err);
    CHECK(r.status == 0);
    CHECK(std::filesystem::exists(png));
}

}  // namespace

// In the thin extrusion's object space the rays' steps are a few ulps
// long; the swept prism's root scan split an interval with no double
// inside forever (render/primitives/swept_prism.cpp).
TEST_CASE("a twisted extrusion 1e-29 thick among ordinary ones renders") {
    renders("thin_twist", "linear_extrude(10, twist = 90) square(6);\n"
                          "linear_extrude(11e-30, twist = 90) square(5);\n"
                          "linear_extrude(10, scale = 2) square(5);\n");
}

// A ray refracted into glass that is unbounded along it never leaves; it
// was traced on from a point at infinity, which Embree's ray check aborts
// on (render/shading.cpp, Shader::inside).
TEST_CASE("glass beside a half-space renders") {
    renders("glass_halfspace", "plane(normal = [0, 1, 1], offset = 2);\n"
                               "for (i = [0:40]) translate([10 * cos(9 * i), 10 * sin(9 * i), 8]) sphere(0.2);\n"
                               "material(color = [1, 1, 1], transparency = 0.95, ior = 1.5) translate([-2, -1.5, 1.7]) sphere(1.7);\n");
}

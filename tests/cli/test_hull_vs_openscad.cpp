// hull(), minkowski() and resize() against OpenSCAD 2021 itself (the
// reference of docs/spec.md §11): the same .scad file exported by
// `openscad -o x.off` and measured by `kerf measure`. OpenSCAD's facets
// ($fn = 64) lie inside the curves, so its volume is a little smaller;
// the boxes agree to the facets' sag. Skipped where openscad is missing.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <fstream>

#include "tests/cli/run_kerf.hpp"

namespace {

struct OffSolid {
    double volume = 0;
    std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};

OffSolid read_off(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::string magic;
    std::size_t nv = 0, nf = 0, ne = 0;
    in >> magic >> nv >> nf >> ne;
    std::vector<std::array<double, 3>> v(nv);
    OffSolid s;
    for (auto& p : v) {
        in >> p[0] >> p[1] >> p[2];
        for (int k = 0; k < 3; ++k) s.lo[k] = std::min(s.lo[k], p[k]), s.hi[k] = std::max(s.hi[k], p[k]);
    }
    for (std::size_t f = 0; f < nf; ++f) {
        std::size_t n = 0;
        in >> n;
        std::vector<std::size_t> idx(n);
        for (auto& i : idx) in >> i;
        for (std::size_t k = 1; k + 1 < n; ++k) {
            const auto &a = v[idx[0]], &b = v[idx[k]], &c = v[idx[k + 1]];
            s.volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                         a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
        }
    }
    s.volume = std::abs(s.volume);
    return s;
}

double figure(const std::string& out, const std::string& key) {
    const std::size_t at = out.find(key + ": ");
    return at == std::string::npos ? std::nan("") : std::strtod(out.c_str() + at + key.size() + 2, nullptr);
}

// The bounds line's six numbers, "bounds: [[x, y, z], [x, y, z]]".
std::array<double, 6> bounds(const std::string& out) {
    std::array<double, 6> b{};
    std::size_t at = out.find("bounds: ");
    for (double& x : b) {
        at = out.find_first_of("-0123456789", out.find_first_not_of("[], ", at + (&x == &b[0] ? 8 : 0)));
        char* end = nullptr;
        x = std::strtod(out.c_str() + at, &end);
        at = std::size_t(end - out.c_str());
    }
    return b;
}

}  // namespace

TEST_CASE("hull, minkowski and resize measure as OpenSCAD 2021 exports them", "[hull]") {
    if (std::system("command -v openscad >/dev/null 2>&1") != 0) {
        WARN("openscad is not installed: skipped");
        return;
    }
    auto dir = test_dir("hull_openscad");
    const char* scenes[] = {
        "minkowski() { cube([2, 3, 4]); sphere(0.5, $fn = 64); }",
        "hull() { sphere(2, $fn = 64); translate([5, 0, 0]) sphere(1, $fn = 64); }",
        "hull() { cube(1); translate([3, 1, 0]) rotate([0, 0, 30]) cube([1, 2, 0.5]); }",
        "resize([4, 6, 0], auto = [false, false, true]) rotate([0, 0, 45]) cube(1);",
        "minkowski() { cube([2, 2, 2]); cylinder(h = 1, r = 1, $fn = 64); }",
    };
    int k = 0;
    for (const char* text : scenes) {
        INFO(text);
        const std::string name = "s" + std::to_string(k++);
        const std::string scad = write_file(dir / (name + ".scad"), std::string(text) + "\n");
        const std::string off = (dir / (name + ".off")).string();
        REQUIRE(std::system(("cd '" + dir.string() + "' && openscad -o '" + off + "' '" + scad + "' >/dev/null 2>&1").c_str()) == 0);
        const OffSolid want = read_off(off);
        auto r = run_kerf("measure '" + scad + "' --resolution 256", dir);
        REQUIRE(r.status == 0);
        INFO(r.out);
        const double v = figure(r.out, "volume");
        const std::size_t pm = r.out.find("\xc2\xb1");  // "±": the grid's own error estimate
        REQUIRE(pm != std::string::npos);
        const double err = std::strtod(r.out.c_str() + pm + 2, nullptr);
        CHECK(v + err >= want.volume * (1 - 1e-3));
        CHECK(v - err <= want.volume * 1.01);
        const auto b = bounds(r.out);
        for (int i = 0; i < 3; ++i) {
            const double size = want.hi[i] - want.lo[i];
            CHECK(b[i] == Approx(want.lo[i]).margin(5e-3 * size));
            CHECK(b[3 + i] == Approx(want.hi[i]).margin(5e-3 * size));
        }
    }
}

// A pattern lives in the coordinates of its material() call (docs/language.md,
// "Patterns"): transforms outside the call move it with the solid, transforms
// inside move the solid through it; pattern_scale and pattern_transform
// resize and turn it. Checked on rendered pixels of a slab's top face,
// lit straight from above, against the closed forms of the cells.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "render/render.hpp"
#include "render/shading.hpp"
#include "tests/lower/script_scene.hpp"
#include "tests/render/same_bytes.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

// The top face of a 40×40 slab at z = 0.5 under a light from straight above,
// so every point of it is lit the same: a white cell shows `white`, a black cell 0.
csg::Scene slab(const std::string& material, const std::string& outside = "", const std::string& inside = "") {
    csg::Scene s = lowered(outside + " material(" + material + ", specular = 0) " + inside +
                           " translate([-20, -20, -0.5]) cube([40, 40, 1]);");
    csg::Light l;
    l.directional = true;
    l.direction = {0, 0, -1};
    s.lights = {l};
    return s;
}

// The red channel where a ray straight down hits the top at (x, y).
double seen(const csg::Scene& s, double x, double y) {
    const render::CsgTracer tracer(s, false);
    const render::Shader shader(s, tracer, 4);
    render::ThreadState ts;
    const double inf = std::numeric_limits<double>::infinity();
    return shader.radiance(render::TraceRay{{x, y, 10}, {0, 0, -1}, 0, inf}, 0, ts).x;
}

double cell(double x) { return double((long(std::floor(x)) % 2 + 2) % 2); }

const char* kChecker = "color = \"white\", color2 = \"black\", pattern = \"checker\"";

}  // namespace

TEST_CASE("a checker slab's pixels: the cell of each point by the closed form", "[lower][patterns]") {
    const csg::Scene s = slab(kChecker);
    const double white = seen(s, 0.5, 0.5);  // floor sum 0 + 0 + 0: color
    REQUIRE(white > 0.1);
    for (double x = -3.75; x < 4; x += 0.5)
        for (double y = -3.75; y < 4; y += 0.5) {
            INFO(x << ", " << y);
            // z = 0.5 lies in the cell floor(z) = 0.
            const double v = cell(std::floor(x) + std::floor(y));
            CHECK(seen(s, x, y) == Approx(v == 0 ? white : 0).margin(1e-12));
        }
}

TEST_CASE("a pattern moves with transforms outside its material() call, not inside", "[lower][patterns]") {
    const csg::Scene ref = slab(kChecker);
    const double white = seen(ref, 0.5, 0.5);
    // Moved by 1 along x outside: the cell under world x is the one of x − 1.
    const csg::Scene moved = slab(kChecker, "translate([1, 0, 0])");
    // Moved inside: the slab moves through a fixed pattern.
    const csg::Scene through = slab(kChecker, "", "translate([1, 0, 0])");
    // An inner color() keeps the pattern and the space of the call that set it.
    const csg::Scene recoloured = slab(kChecker, "", "translate([1, 0, 0]) color(\"white\")");
    for (double x = -2.75; x < 3; x += 0.5) {
        INFO(x);
        CHECK(seen(moved, x, 0.5) == Approx(cell(std::floor(x - 1)) == 0 ? white : 0).margin(1e-12));
        CHECK(seen(through, x, 0.5) == Approx(cell(std::floor(x)) == 0 ? white : 0).margin(1e-12));
        CHECK(seen(recoloured, x, 0.5) == Approx(cell(std::floor(x)) == 0 ? white : 0).margin(1e-12));
    }
    // Scaled by 2 outside: cells 2 units wide.
    const csg::Scene scaled = slab(kChecker, "scale([2, 2, 1])");
    for (double x = -3.25; x < 4; x += 0.5) CHECK(seen(scaled, x, 0.25) == Approx(cell(std::floor(x / 2)) == 0 ? white : 0).margin(1e-12));
}

TEST_CASE("stripes: pattern_scale sets the period, pattern_transform turns it", "[lower][patterns]") {
    const std::string stripes = "color = \"white\", color2 = \"black\", pattern = \"stripes\"";
    const csg::Scene s = slab(stripes + ", pattern_scale = 0.5");
    const double white = seen(s, 0.25, 0);
    REQUIRE(white > 0.1);
    for (double x = -2.05; x < 2; x += 0.2) CHECK(seen(s, x, 3.3) == Approx(cell(std::floor(x / 0.5)) == 0 ? white : 0).margin(1e-12));
    // Turned 90° about z (rotation matrix rows): the stripes run across y.
    const csg::Scene turned = slab(stripes + ", pattern_transform = [[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0]]");
    for (double y = -2.05; y < 2; y += 0.2) {
        INFO(y);
        // Pattern point = R⁻¹ p: x' = y, so the cell is floor(y).
        CHECK(seen(turned, 7.3, y) == Approx(cell(std::floor(y)) == 0 ? white : 0).margin(1e-12));
    }
}

TEST_CASE("gradient: the colour at known points is the linear blend by frac(x)", "[lower][patterns]") {
    const csg::Scene s = slab("color = \"black\", color2 = \"white\", pattern = \"gradient\", pattern_scale = 4");
    const double full = seen(slab("color = \"white\""), 0, 0);
    for (double x : {-3.0, -1.0, 0.5, 1.0, 2.0, 3.5, 7.9}) {
        INFO(x);
        const double f = x / 4 - std::floor(x / 4);
        CHECK(seen(s, x, 1.7) == Approx(f * full).margin(1e-12));
    }
}

TEST_CASE("patterned renders hold the same bytes on 1 and 2 threads", "[lower][patterns]") {
    for (const char* p : {"checker", "noise", "marble", "wood"}) {
        INFO(p);
        csg::Scene s = slab(std::string("color = \"white\", color2 = [0.2, 0.1, 0], pattern = \"") + p + "\", pattern_scale = 3");
        s.camera.position = {0, -8, 12};
        s.camera.look_at = {0, 0, 0};
        render::RenderOptions o;
        o.width = 96, o.height = 64, o.spp = 4;
        const auto [one, two] = on_1_and_2_threads(s, o);
        CHECK(same_bytes(one, two));
    }
}

// The `%` and `#` ghosts end to end (csg/ghosts.hpp): script, lowering,
// render. A ghost's pixels are checked against the blend written out by
// hand (front face over back face over what lies behind, OpenSCAD's colours
// and alpha), the solid against the membership oracle and against the same
// script without the modifier: ghosts change no pixel outside themselves,
// cast no shadow, and are not in the solid, its AOVs or its measure.
#include <catch2/catch.hpp>

#include <cmath>

#include "csg/ghosts.hpp"
#include "csg/membership.hpp"
#include "render/measure/measure.hpp"
#include "render/render.hpp"
#include "tests/lower/script_scene.hpp"

using kerf::csg::GhostKind;
using kerf::test::evaluated;

namespace {

constexpr int kSize = 64;

kerf::csg::Scene scene_of(const std::string& text, bool ghosts = true) {
    kerf::LowerOptions o;
    o.ghosts = ghosts;
    return kerf::lower_to_csg(evaluated(text).graph, o);
}

kerf::render::Image draw(const kerf::csg::Scene& s, kerf::render::RenderOptions o = {}) {
    o.width = o.height = kSize;
    o.threads = 2;
    return kerf::render::render(s, o);
}

glm::dvec3 pixel(const kerf::render::Image& im, int x, int y) {
    const float* p = &im.pixels[(std::size_t(y) * im.width + x) * im.channels];
    return {p[0], p[1], p[2]};
}

// Equal within float storage (the image keeps 32-bit floats).
bool near(const glm::dvec3& a, const glm::dvec3& b) { return glm::all(glm::lessThan(glm::abs(a - b), glm::dvec3(1e-6))); }

// What a ray straight through a ghost box or slab sees (both faces facing
// the eye, so lit fully): its front face over its back face over `behind`.
glm::dvec3 through_ghost(GhostKind kind, const glm::dvec3& behind) {
    const kerf::csg::Material g = kerf::csg::ghost_material(kind);
    const double a = 1 - g.transparency;
    return a * g.color + (1 - a) * (a * g.color + (1 - a) * behind);
}

// Orthographic views along +y (the `%` scene) and down -z (the `#` one),
// 8 units across: pixel (x, y) looks at x − 4 + (x + 0.5)/8 across.
const char* kSide =
    "camera(position = [0, -20, 0], look_at = [0, 0, 0], projection = \"orthographic\", height = 8);\n"
    "light(position = [-10, -20, 10]);\nbackground([0.25, 0.5, 0.75]);\n";
const char* kTop =
    "camera(position = [0, 0, 20], look_at = [0, 0, 0], up = [0, 1, 0], projection = \"orthographic\", height = 16);\n"
    "light(position = [5, 5, 30]);\nbackground([0.25, 0.5, 0.75]);\n";

int column(double x, double across) { return int(std::floor((x / across + 0.5) * kSize)); }

}  // namespace

TEST_CASE("a % cube beside a sphere: a grey translucent ghost, not in the solid", "[ghosts]") {
    const std::string text = std::string(kSide) + "translate([-2, 0, 0]) sphere(1.5);\n%translate([2, 0, 0]) cube(2, center = true);\n";
    const kerf::csg::Scene with = scene_of(text), without = scene_of(text, false);
    REQUIRE(with.ghosts.size() == 1);
    CHECK(without.ghosts.empty());
    const kerf::render::Image a = draw(with), b = draw(without);
    const glm::dvec3 bg = kerf::csg::srgb_to_linear(glm::dvec3(0.25, 0.5, 0.75));
    int ghost_pixels = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double px = (x + 0.5) / kSize * 8 - 4, pz = 4 - (y + 0.5) / kSize * 8;
            const glm::dvec3 got = pixel(a, x, y), plain = pixel(b, x, y);
            INFO("pixel " << x << ", " << y);
            if (std::abs(px - 2) < 0.9 && std::abs(pz) < 0.9) {  // only the ghost, well inside its outline
                ++ghost_pixels;
                CHECK(near(plain, bg));
                const glm::dvec3 want = through_ghost(GhostKind::Background, bg);
                for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(want[k]).epsilon(1e-5));
            } else if (std::abs(px - 2) > 1.1 || std::abs(pz) > 1.1) {
                CHECK(got == plain);  // no shadow, no change elsewhere (the sphere included)
            }
        }
    CHECK(ghost_pixels > 100);
    // Not in the solid: its volume is the sphere's alone.
    kerf::render::MeasureOptions mo;
    mo.resolution = 128;
    const kerf::render::Measurement m = kerf::render::measure(with, mo);
    const double sphere = 4.0 / 3 * M_PI * 1.5 * 1.5 * 1.5;
    CHECK(std::abs(m.volume - sphere) <= std::max(3 * m.volume_error, 1e-3 * sphere));
    CHECK_FALSE(kerf::csg::contains(with, {2, 0, 0}));
}

TEST_CASE("a # subtrahend: the hole is cut and a pink ghost shows where it is", "[ghosts]") {
    const std::string body = "difference() { cube(10, center = true); #cylinder(r = 3, h = 14, center = true); }\n";
    const kerf::csg::Scene with = scene_of(std::string(kTop) + body);
    const kerf::csg::Scene plain = scene_of(std::string(kTop) + "difference() { cube(10, center = true); cylinder(r = 3, h = 14, center = true); }\n");
    REQUIRE(with.ghosts.size() == 1);
    // The hole is cut: the oracle, and the depth AOV, which sees the solid only.
    CHECK_FALSE(kerf::csg::contains(with, {0, 0, 0}));
    CHECK(kerf::csg::contains(with, {4, 4, 0}));
    kerf::render::RenderOptions depth;
    depth.aov = kerf::render::Aov::Depth;
    const kerf::render::Image d = draw(with, depth), dp = draw(plain, depth);
    CHECK(d.pixels == dp.pixels);
    const int centre = column(0.1, 16), corner = column(4, 16);
    CHECK_FALSE(std::isfinite(d.pixels[std::size_t(centre) * kSize + centre]));          // through the hole
    CHECK(d.pixels[std::size_t(corner) * kSize + corner] == Approx(15).epsilon(1e-9));  // the top at z = 5
    // The colour: pink over the hole (the ghost's top and bottom over the
    // background), the plain solid elsewhere away from the hole.
    const kerf::render::Image c = draw(with), cp = draw(plain);
    const glm::dvec3 bg = kerf::csg::srgb_to_linear(glm::dvec3(0.25, 0.5, 0.75));
    const glm::dvec3 want = through_ghost(GhostKind::Highlight, bg), got = pixel(c, centre, centre);
    for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(want[k]).epsilon(1e-5));
    CHECK(near(pixel(cp, centre, centre), bg));
    CHECK(pixel(c, corner, corner) == pixel(cp, corner, corner));
}

TEST_CASE("a # part on the solid's surface: its faces over the solid's own", "[ghosts]") {
    // The ghost's front face is the solid's (within the tracer's surface
    // tolerance); its back face lies behind the solid and is hidden.
    const std::string body = "sphere(1);\ntranslate([2, 0, 0]) cube(2, center = true);\n";
    const kerf::render::Image hi = draw(scene_of(std::string(kSide) + "sphere(1);\n#translate([2, 0, 0]) cube(2, center = true);\n"));
    const kerf::render::Image plain = draw(scene_of(std::string(kSide) + body));
    const kerf::csg::Material pink = kerf::csg::ghost_material(GhostKind::Highlight);
    const double a = 1 - pink.transparency;
    const int x = column(2, 8), y = kSize / 2;
    const glm::dvec3 want = a * pink.color + (1 - a) * pixel(plain, x, y), got = pixel(hi, x, y);
    for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(want[k]).epsilon(1e-5));
    CHECK(pixel(hi, kSize / 2, y) == pixel(plain, kSize / 2, y));  // the sphere
}

TEST_CASE("ghosts with --alpha, a crop and the path tracer", "[ghosts]") {
    const std::string text = std::string(kSide) + "sphere(1);\n%translate([2, 0, 0]) cube(2, center = true);\n";
    const kerf::csg::Scene s = scene_of(text);
    const int x = column(2, 8), y = kSize / 2;
    const double a = 1 - kerf::csg::ghost_material(GhostKind::Background).transparency;
    // --alpha: the ghost over the background is as opaque as its two faces.
    kerf::render::RenderOptions alpha;
    alpha.alpha = kerf::render::Alpha::Straight;
    const kerf::render::Image im = draw(s, alpha);
    CHECK(im.pixels[(std::size_t(y) * kSize + x) * 4 + 3] == Approx(1 - (1 - a) * (1 - a)).epsilon(1e-6));
    CHECK(im.pixels[(std::size_t(y) * kSize + kSize / 2) * 4 + 3] == 1);  // the sphere
    CHECK(im.pixels[3] == 0);                                             // the background
    // A crop (and so a farm band, whose tiles fall elsewhere) has the same pixels.
    kerf::render::RenderOptions crop;
    crop.crop = std::array<int, 4>{x - 5, y - 7, x + 9, y + 3};
    const kerf::render::Image full = draw(s), part = draw(s, crop);
    for (int j = 0; j < part.height; ++j)
        for (int i = 0; i < part.width; ++i) CHECK(pixel(part, i, j) == pixel(full, x - 5 + i, y - 7 + j));
    // The path tracer: the same ghost over its own (background) miss.
    kerf::render::RenderOptions path;
    path.integrator = kerf::render::Integrator::Path;
    path.spp = 2;
    const glm::dvec3 bg = kerf::csg::srgb_to_linear(glm::dvec3(0.25, 0.5, 0.75));
    const glm::dvec3 want = through_ghost(GhostKind::Background, bg), got = pixel(draw(s, path), x, y);
    for (int k = 0; k < 3; ++k) CHECK(got[k] == Approx(want[k]).epsilon(1e-5));
    // Fog: each ghost face fogged by its own distance (19 and 21 from the
    // camera plane), over the fog's colour that a miss sees.
    const kerf::csg::Scene fogged = scene_of(text + "fog(20, [1, 1, 1]);\n");
    const kerf::csg::Material g = kerf::csg::ghost_material(GhostKind::Background);
    auto fog = [&](double d) { return std::exp(-d / 20) * g.color + (1 - std::exp(-d / 20)) * glm::dvec3(1); };
    const glm::dvec3 seen = a * fog(19) + (1 - a) * (a * fog(21) + (1 - a) * glm::dvec3(1)), fog_got = pixel(draw(fogged), x, y);
    for (int k = 0; k < 3; ++k) CHECK(fog_got[k] == Approx(seen[k]).epsilon(1e-5));
}

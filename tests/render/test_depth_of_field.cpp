// Depth of field against the thin-lens closed form: a lens A across focused
// at f blurs a point at depth d into a disk A·|d − f|/d across on the plane
// of focus, so a sharp edge at depth d becomes a ramp whose profile is the
// disk's cumulative width: the share of the disk left of s·radius is
// ½ + (s√(1 − s²) + asin s)/π. The plane of focus itself stays sharp: its
// pixels are the pinhole camera's under the same pixel samples.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "render/camera.hpp"
#include "tests/render/same_bytes.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

constexpr int W = 64, H = 48;
constexpr double kFov = 40;

double disk_share(double s) {
    s = std::clamp(s, -1.0, 1.0);
    return 0.5 + (s * std::sqrt(1 - s * s) + std::asin(s)) / std::numbers::pi;
}

// Camera at the origin looking along +y with a lens; the solids emit 1
// (black, so no ambient) into a black background with no lights.
csg::Scene lens_scene(const Tree& t, std::vector<csg::Material> mats, double aperture, double focus, int samples) {
    csg::Scene s = make_scene(t, std::move(mats));
    s.lights.clear();
    s.background = glm::dvec3(0.0);
    s.camera.position = {0, 0, 0};
    s.camera.look_at = {0, 1, 0};
    s.camera.up = {0, 0, 1};
    s.camera.fov = kFov;
    s.camera.aperture = aperture;
    s.camera.focal_distance = focus;
    s.camera.blur_samples = std::uint32_t(samples);
    return s;
}

csg::Material glow() {
    csg::Material m;
    m.color = glm::dvec3(0.0);
    m.specular = 0;
    m.emission = glm::dvec3(1.0);
    return m;
}

}  // namespace

TEST_CASE("depth of field: a sharp edge at depth d blurs over A·|d - f|/d, the thin-lens disk", "[render][dof]") {
    struct Case { double d, f, a; };
    for (const Case c : {Case{20, 10, 2}, Case{6, 10, 1}, Case{14, 10, 3}}) {
        // The edge x = 0 of a card x > 0 facing the camera at depth d.
        const Tree wall = leaf(box({0, c.d, -1e3}, {1e3, c.d * (1 + 1e-6), 1e3}));  // thin: its side stays unseen
        const csg::Scene s = lens_scene(wall, {glow()}, c.a, c.f, 256);
        render::RenderOptions o;
        o.width = W, o.height = H;
        const render::Image im = render::render(s, o);
        // The mean of each column over all rows (every row sees the same edge).
        std::vector<double> profile(W, 0.0);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) profile[x] += im.at(x, y, 0) / H;
        // The closed form: blur diameter in pixels, the ramp centred on the
        // image's middle (x = 0 projects there through the lens centre), each
        // pixel the mean of the ramp over its width.
        const double pixel = 2 * std::tan(glm::radians(kFov / 2)) * c.f / H;  // focal-plane units per pixel
        const double blur = c.a * std::abs(c.d - c.f) / c.d / pixel;
        double worst = 0, var = 0, var_want = 0, total = 0;
        std::vector<double> want(W);
        for (int x = 0; x < W; ++x) {
            double sum = 0;
            for (int k = 0; k < 200; ++k) sum += disk_share((x + (k + 0.5) / 200 - W / 2.0) / (blur / 2));
            want[x] = sum / 200;
            worst = std::max(worst, std::abs(profile[x] - want[x]));
        }
        // The width measured from the image: the ramp's slope is a
        // semicircle of variance (blur/2)²/4, widened by the pixel's box
        // twice (its samples, then differencing: 1/12 each).
        for (int x = 0; x + 1 < W; ++x) {
            const double slope = profile[x + 1] - profile[x], at = x + 1 - W / 2.0;
            var += slope * at * at, var_want += (want[x + 1] - want[x]) * at * at, total += slope;
        }
        const double measured = 4 * std::sqrt(var / total - 2.0 / 12);
        INFO("d " << c.d << " f " << c.f << " A " << c.a << ": blur " << blur << " px, measured " << measured
                  << " px, worst column error " << worst);
        CHECK(worst < 0.02);  // noise: σ ≈ 0.5/√(256·48) per column
        CHECK(measured == Approx(blur).epsilon(0.05));
        CHECK(4 * std::sqrt(var_want - 2.0 / 12) == Approx(blur).epsilon(0.02));  // the width formula itself
        CHECK(total == Approx(1).margin(0.01));
    }
}

TEST_CASE("depth of field: the plane of focus is the pinhole image, any thread count gives the same bytes", "[render][dof]") {
    // A checkered wall exactly at the focal distance: every lens ray of a
    // sample meets the pinhole ray's point there, so colours agree.
    csg::Material checker;
    checker.color = glm::dvec3(1.0);
    checker.color2 = glm::dvec3(0.2, 0.3, 0.9);
    checker.specular = 0;
    checker.pattern = csg::Pattern::Checker;
    const double f = 10.5;
    const Tree wall = leaf(box({-1e3, f, -1e3}, {1e3, f + 1, 1e3}));
    const csg::Scene lens = lens_scene(wall, {checker}, 1.5, f, 16);
    csg::Scene pinhole = lens;
    pinhole.camera.aperture = 0;
    render::RenderOptions o;
    o.width = W, o.height = H;
    const render::Image blurred = render::render(lens, o);
    o.spp = 16;  // the pinhole with the same pixel samples
    const render::Image sharp = render::render(pinhole, o);
    double worst = 0, lo = 1, hi = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            worst = std::max(worst, double(std::abs(blurred.at(x, y, 2) - sharp.at(x, y, 2))));
            lo = std::min(lo, double(sharp.at(x, y, 0))), hi = std::max(hi, double(sharp.at(x, y, 0)));
        }
    CHECK(hi - lo > 0.07);  // the checker shows (ambient 0.1 × albedo 1 or 0.2)
    CHECK(worst < 1e-6);
    // Off the plane of focus the same wall blurs: the image differs.
    csg::Scene off = lens;
    off.camera.focal_distance = 4;
    o.spp = 1;
    const render::Image soft = render::render(off, o);
    double moved = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) moved = std::max(moved, double(std::abs(soft.at(x, y, 0) - sharp.at(x, y, 0))));
    CHECK(moved > 0.02);
    o.width = 40, o.height = 40;
    const auto [one, two] = on_1_and_2_threads(off, o);
    CHECK(same_bytes(one, two));
    // A crop renders the same pixels (seeded by full-image coordinates).
    o.crop = std::array<int, 4>{5, 7, 30, 33};
    const render::Image part = render::render(off, o);
    bool same = true;
    for (int y = 7; y < 33; ++y)
        for (int x = 5; x < 30; ++x) same = same && part.at(x - 5, y - 7, 1) == one.at(x, y, 1);
    CHECK(same);
}

TEST_CASE("thin lens rays: from the aperture disk through the pinhole ray's point at the focal distance", "[camera][dof]") {
    csg::Camera c;
    c.position = {1, 2, 3};
    c.look_at = {1, 12, 3};
    c.aperture = 0.8;
    c.focal_distance = 5;
    const render::CameraModel cam(c, 30, 20);
    glm::dvec3 po, pd;
    cam.ray(7.3, 4.1, po, pd);
    const glm::dvec3 focus = po + pd * (5 / pd.y);  // the pinhole ray at depth 5
    double reach = 0;
    for (double lx : {0.0, 0.13, 0.5, 0.77, 0.999})
        for (double ly : {0.01, 0.5, 0.6, 0.98}) {
            glm::dvec3 o, d;
            cam.ray_through_lens(7.3, 4.1, {lx, ly}, o, d);
            CHECK(o.y == Approx(2));  // on the lens plane
            reach = std::max(reach, glm::length(o - c.position));
            CHECK(glm::length(o - c.position) <= 0.4 + 1e-12);
            const glm::dvec3 at = o + d * ((focus.y - o.y) / d.y);
            CHECK(glm::length(at - focus) < 1e-12);
        }
    CHECK(reach > 0.39);  // the disk's rim is reached
    glm::dvec3 o, d;
    cam.ray_through_lens(7.3, 4.1, {0.5, 0.5}, o, d);  // the lens centre: the pinhole ray
    CHECK(o == c.position);
    CHECK(glm::length(glm::normalize(d) - pd) < 1e-12);
}

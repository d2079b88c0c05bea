// The studio look (docs/spec.md §12 "Default look", docs/language.md "The
// default look"), judged by closed forms written here independently of
// lower/studio.cpp and render/: the pinhole of docs/spec.md §6 for the
// framing, the bounding box for the ground's height, and for the shadow the
// cones from a ground point to the key light's sphere and to a sphere solid.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "render/render.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;

namespace {

struct Basis {
    glm::dvec3 f, r, u;
    explicit Basis(const csg::Camera& c) {
        f = glm::normalize(c.look_at - c.position);
        r = glm::normalize(glm::cross(f, c.up));
        u = glm::cross(r, f);
    }
};

// Pixel coordinates of a world point in a W×H image (docs/spec.md §6).
glm::dvec2 project(const csg::Camera& c, const glm::dvec3& p, double W, double H) {
    const Basis b(c);
    const glm::dvec3 d = p - c.position;
    const double depth = glm::dot(d, b.f), half_h = std::tan(glm::radians(c.fov) / 2);
    const double x = glm::dot(d, b.r) / depth / (half_h * W / H), y = glm::dot(d, b.u) / depth / half_h;
    return {(x + 1) / 2 * W, (1 - y) / 2 * H};
}

// The direction through pixel centre (x + 0.5, y + 0.5) (docs/spec.md §6).
glm::dvec3 through(const csg::Camera& c, int x, int y, double W, double H) {
    const Basis b(c);
    const double half_h = std::tan(glm::radians(c.fov) / 2);
    const double sx = (2 * (x + 0.5) / W - 1) * half_h * W / H, sy = (1 - 2 * (y + 0.5) / H) * half_h;
    return glm::normalize(b.f + sx * b.r + sy * b.u);
}

csg::Scene lower(const std::string& text, LowerOptions o = {}, const std::string& path = "test.sdl") {
    return lower_to_csg(test::evaluated(text, path).graph, o);
}

glm::dvec3 corner(const csg::Aabb& b, int k) {
    return {(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z};
}

}  // namespace

// `img` (rendered with `o`, 160 wide, 2 threads) again with 1 thread and
// with a crop: the same bytes.
void same_for_threads_and_crop(const csg::Scene& s, render::RenderOptions o, const render::Image& img) {
    o.threads = 1;
    CHECK(render::render(s, o).pixels == img.pixels);
    o.crop = std::array<int, 4>{13, 7, 141, 101};
    const render::Image part = render::render(s, o);
    for (int y = 7; y < 101; ++y)
        for (int x = 13; x < 141; ++x)
            for (int ch = 0; ch < 3; ++ch)
                REQUIRE(part.pixels[(std::size_t(y - 7) * 128 + (x - 13)) * 3 + ch] == img.pixels[(std::size_t(y) * 160 + x) * 3 + ch]);
}

TEST_CASE("studio framing: the bounding box spans 80 % of the tighter image side, centred") {
    struct Case { std::string solid; double W, H; };
    for (const Case& c : {Case{"cube([100, 60, 3]);", 800, 600},            // a flat part: width-bound
                          Case{"cube([1, 1, 10]);", 800, 600},              // a tower: height-bound
                          Case{"translate([5, -7, 2]) sphere(3);", 1920, 1080},
                          Case{"cube([100, 60, 3]);", 600, 800},            // portrait
                          Case{"rotate([20, 30, 40]) cube([4, 1, 2]);", 640, 640}}) {
        INFO(c.solid << " in " << c.W << "x" << c.H);
        const csg::Scene s = lower(c.solid, {Look::Studio, c.W / c.H});
        const csg::Aabb box = s.bounds();
        CHECK(s.camera.fov == 40);
        CHECK(s.camera.up == glm::dvec3(0, 0, 1));
        glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
        for (int k = 0; k < 8; ++k) {
            const glm::dvec2 px = project(s.camera, corner(box, k), c.W, c.H);
            lo = glm::min(lo, px), hi = glm::max(hi, px);
        }
        const double fx = (hi.x - lo.x) / c.W, fy = (hi.y - lo.y) / c.H;
        CHECK(std::max(fx, fy) == Approx(0.8).epsilon(1e-6));
        CHECK(std::min(fx, fy) <= 0.8 + 1e-6);
        CHECK((lo.x + hi.x) / 2 == Approx(c.W / 2).margin(1e-6 * c.W));  // centred both ways
        CHECK((lo.y + hi.y) / 2 == Approx(c.H / 2).margin(1e-6 * c.H));
        // Seen from the default front-right direction.
        const glm::dvec3 back = glm::normalize(s.camera.position - s.camera.look_at);
        CHECK(glm::dot(back, glm::normalize(glm::dvec3(1, -1, 0.8))) == Approx(1));
    }
    // An unbounded solid is framed by its bounded parts: the sphere beside a half-space.
    const csg::Scene half = lower("plane([0, 0, 1], -1); translate([10, 0, 0]) sphere(1);");
    const csg::Aabb ball{glm::dvec3(9, -1, -1), glm::dvec3(11, 1, 1)};
    glm::dvec2 blo(HUGE_VAL), bhi(-HUGE_VAL);
    for (int k = 0; k < 8; ++k) {
        const glm::dvec2 px = project(half.camera, corner(ball, k), 800, 600);
        blo = glm::min(blo, px), bhi = glm::max(bhi, px);
    }
    CHECK(std::max((bhi.x - blo.x) / 800, (bhi.y - blo.y) / 600) == Approx(0.8).epsilon(1e-6));
    // A flat part at 800×600 (the case) fills 80 % of the width, not about half.
    const csg::Scene flat = lower("cube([100, 60, 3]);");
    glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (int k = 0; k < 8; ++k) {
        const glm::dvec2 px = project(flat.camera, corner(flat.bounds(), k), 800, 600);
        lo = glm::min(lo, px), hi = glm::max(hi, px);
    }
    CHECK((hi.x - lo.x) / 800 == Approx(0.8).epsilon(1e-6));
}

TEST_CASE("studio ground: at the solid's lowest point, outside the CSG, with the studio lights only") {
    // A sphere of radius 2 centred at z = 3 and a box from z = 1.5: min z = 1.
    const csg::Scene s = lower("translate([0, 0, 3]) sphere(2); translate([5, 0, 1.5]) cube(1);");
    CHECK(s.ground.on);
    CHECK(s.ground.z == Approx(1).margin(1e-12));
    CHECK(s.leaves.size() == 2);  // no leaf for the ground: measure, dump's tree and the oracle never see it
    const csg::Scene plain = lower("translate([0, 0, 3]) sphere(2); translate([5, 0, 1.5]) cube(1);", {Look::Plain});
    CHECK(plain.leaves.size() == s.leaves.size());
    CHECK(plain.nodes.size() == s.nodes.size());
    CHECK(s.bounds().lo == plain.bounds().lo);
    CHECK(s.bounds().hi == plain.bounds().hi);
    // The lights: a soft key above the solid, a shadowless fill; a light background.
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].radius > 0);
    CHECK(s.lights[0].shadows);
    CHECK(s.lights[0].position.z > s.bounds().hi.z + s.lights[0].radius);
    CHECK(!s.lights[1].shadows);
    CHECK(s.background == glm::dvec3(0.5));
    // Key above-left of the camera, fill to its right.
    const Basis b(s.camera);
    CHECK(glm::dot(s.lights[0].position - s.camera.position, b.r) < 0);
    CHECK(glm::dot(s.lights[1].position - s.camera.position, b.r) > 0);

    // A camera and no light: that camera, the studio lights and ground.
    const csg::Scene cam = lower("camera(position = [0, -20, 4]); sphere(1);");
    CHECK(cam.camera.position == glm::dvec3(0, -20, 4));
    CHECK(cam.ground.on);
    CHECK(cam.lights.size() == 2);
    // A light and no camera: the studio camera, the script's light, no
    // ground and the dark background its light was chosen against.
    const csg::Scene lit = lower("light(position = [3, 3, 9]); sphere(1);");
    CHECK(!lit.ground.on);
    CHECK(lit.lights.size() == 1);
    CHECK(lit.background == glm::dvec3(0.2));
    CHECK(lit.camera.position == lower("sphere(1);").camera.position);
    // A background statement is kept.
    CHECK(lower("background(\"black\"); sphere(1);").background == glm::dvec3(0));
    // OpenSCAD's viewport camera is kept, lit by the studio.
    const csg::Scene vp = lower("$vpr = [60, 0, 30]; $vpd = 40; cube(5);", {}, "test.scad");
    CHECK(vp.camera.fov != 40);
    CHECK(vp.ground.on);
    CHECK(vp.lights.size() == 2);
    // Unbounded (a half-space is its own floor) or empty: no ground.
    CHECK(!lower("plane([0, 0, 1]); sphere(1);").ground.on);
    CHECK(!lower("").ground.on);
}

TEST_CASE("the plain look (--look plain) keeps the docs/spec.md §6 defaults") {
    const csg::Scene s = lower("cube([100, 60, 3]);", {Look::Plain});
    CHECK(!s.ground.on);
    CHECK(s.background == glm::dvec3(0.2));
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].radius == 0);
    CHECK(glm::length(s.lights[1].position - s.camera.position) == Approx(0).margin(1e-12));
    const glm::dvec3 centre = 0.5 * (s.bounds().lo + s.bounds().hi);
    CHECK(glm::length(s.camera.look_at - centre) == Approx(0).margin(1e-9));
}

TEST_CASE("studio ground: a full shadow under a sphere, the background beyond") {
    // A unit sphere resting on the ground z = 0.
    const csg::Scene s = lower("translate([0, 0, 1]) sphere(1);");
    REQUIRE(s.ground.on);
    REQUIRE(s.ground.z == Approx(0).margin(1e-12));
    const csg::Light& key = s.lights[0];
    const glm::dvec3 centre(0, 0, 1);
    const int W = 160, H = 120;
    render::RenderOptions o;
    o.width = W, o.height = H, o.threads = 2, o.spp = 1;
    const render::Image img = render::render(s, o);
    REQUIRE(img.channels == 3);
    auto value = [&](int x, int y) { return double(img.pixels[(std::size_t(y) * W + x) * 3 + 1]); };
    // Classify each pixel centre's ray that reaches the ground without
    // meeting the sphere: in the key's umbra (every ray to the light's
    // sphere is blocked: the light's cone lies inside the sphere's), or
    // where no ray to the light can meet the sphere at all.
    int umbra = 0, open = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const glm::dvec3 o3 = s.camera.position, d = through(s.camera, x, y, W, H);
            if (!(d.z < 0)) continue;
            const glm::dvec3 g = o3 + d * (-o3.z / d.z);
            const double along = glm::dot(centre - o3, d);
            if (glm::length(o3 + along * d - centre) < 1 + 1e-3) continue;  // the sphere is (nearly) in front
            const glm::dvec3 to_l = key.position - g, to_c = centre - g;
            const double theta = std::acos(std::clamp(glm::dot(glm::normalize(to_l), glm::normalize(to_c)), -1.0, 1.0));
            const double a_l = std::asin(key.radius / glm::length(to_l)), a_c = std::asin(1 / glm::length(to_c));
            INFO("pixel " << x << "," << y);
            if (theta + a_l < a_c - 1e-3) {
                ++umbra;  // fully shadowed: background × (1 − 0.6)
                CHECK(value(x, y) == Approx(0.5 * 0.4).margin(1e-6));
            } else if (theta > a_l + a_c + 1e-3) {
                ++open;  // the ground beyond: exactly the background
                CHECK(value(x, y) == Approx(0.5).margin(1e-9));
            }
        }
    CHECK(umbra > 20);
    CHECK(open > 5000);

    // Same bytes for any thread count and any crop (the ground's tiles are
    // not culled where a shadow can fall).
    same_for_threads_and_crop(s, o, img);
}

TEST_CASE("studio ground: adaptive AA refines the silhouette, not the soft shadow's grain, same bytes for any threads and crop") {
    const csg::Scene s = lower("translate([0, 0, 1]) sphere(1);");
    const int W = 160, H = 120;
    render::RenderOptions o;
    o.width = W, o.height = H, o.threads = 2, o.adaptive = true;
    render::RenderStats stats;
    const render::Image img = render::render(s, o, &stats);
    // Pixels whose 3×3 neighbourhood of centres has both sphere and ground
    // (the closed-form ray–sphere test): where refinement may go.
    auto on_sphere = [&](int x, int y) {
        const glm::dvec3 d = through(s.camera, x, y, W, H), oc = s.camera.position - glm::dvec3(0, 0, 1);
        const double b = glm::dot(oc, d);
        return b * b - (glm::dot(oc, oc) - 1) * glm::dot(d, d) > 0;
    };
    int edge = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            int in = 0, n = 0;
            for (int ny = std::max(0, y - 1); ny <= std::min(H - 1, y + 1); ++ny)
                for (int nx = std::max(0, x - 1); nx <= std::min(W - 1, x + 1); ++nx, ++n) in += on_sphere(nx, ny);
            edge += in > 0 && in < n;
        }
    INFO("refined " << stats.refined_pixels << ", silhouette pixels " << edge);
    CHECK(edge > 100);
    CHECK(stats.refined_pixels <= std::uint64_t(edge));
    same_for_threads_and_crop(s, o, img);
}

TEST_CASE("studio ground: adaptive AA straight to 8-bit codes keeps the ground's pixels, as a crop and the float image do") {
    // A whole 8-bit image stores its first pass's codes a row at a time; the
    // ground's pixels go the general way. A crop always takes the general
    // way: the same bytes. The float image encoded by the sRGB formula is
    // independent but not equal at the edges: an 8-bit image's second pass
    // decodes the centre's colour from its look (docs/quality.md), which
    // moves edge pixels by up to 3 codes here (93 bytes of 57,600); the
    // ground or the background stored in the other's place would move them
    // by tens.
    const csg::Scene s = lower("translate([0, 0, 1]) sphere(1);");
    REQUIRE(s.ground.on);
    const int W = 160, H = 120;
    render::RenderOptions o;
    o.width = W, o.height = H, o.threads = 2, o.adaptive = true;
    const render::Image floats = render::render(s, o);
    o.srgb8 = true;
    const render::Image whole = render::render(s, o);
    REQUIRE(whole.srgb8.size() == std::size_t(W) * H * 3);
    std::size_t differ = 0, far = 0;
    for (std::size_t i = 0; i < floats.pixels.size(); ++i) {
        const double x = std::clamp(double(floats.pixels[i]), 0.0, 1.0);
        const double e = 255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055);
        differ += long(whole.srgb8[i]) != std::lround(e);
        far += std::abs(double(whole.srgb8[i]) - e) > 3.5;
    }
    INFO(differ << " bytes differ from the float image's codes");
    CHECK(far == 0);
    CHECK(differ < floats.pixels.size() / 200);
    o.crop = std::array<int, 4>{13, 7, 141, 101};
    const render::Image part = render::render(s, o);
    REQUIRE(part.srgb8.size() == std::size_t(128) * 94 * 3);
    for (int y = 7; y < 101; ++y)
        for (int x = 13; x < 141; ++x)
            for (int ch = 0; ch < 3; ++ch)
                REQUIRE(part.srgb8[(std::size_t(y - 7) * 128 + (x - 13)) * 3 + ch] == whole.srgb8[(std::size_t(y) * 160 + x) * 3 + ch]);
}

TEST_CASE("studio ground under the path tracer: the shadow catcher of the Whitted tracer") {
    // The ground is drawn where a camera ray misses the solid, by either
    // integrator: every pixel whose centre ray passes clear of the sphere
    // has the Whitted value (checked against the cones above), umbra included.
    const csg::Scene s = lower("translate([0, 0, 1]) sphere(1);");
    REQUIRE(s.ground.on);
    const int W = 160, H = 120;
    render::RenderOptions o;
    o.width = W, o.height = H, o.threads = 2, o.spp = 1, o.adaptive = false;
    const render::Image whitted = render::render(s, o);
    o.integrator = render::Integrator::Path;
    const render::Image path = render::render(s, o);
    const glm::dvec3 centre(0, 0, 1);
    int clear = 0, shadowed = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const glm::dvec3 o3 = s.camera.position, d = through(s.camera, x, y, W, H);
            const double along = glm::dot(centre - o3, d);
            if (glm::length(o3 + along * d - centre) < 1 + 1e-3) continue;  // the sphere is (nearly) in front
            ++clear;
            const std::size_t i = (std::size_t(y) * W + x) * 3 + 1;
            INFO("pixel " << x << "," << y);
            REQUIRE(path.pixels[i] == whitted.pixels[i]);
            shadowed += whitted.pixels[i] < 0.5 - 1e-6;
        }
    CHECK(clear > 5000);
    CHECK(shadowed > 20);
}

TEST_CASE("studio ground: not in the AOVs, transparent with --alpha") {
    const csg::Scene s = lower("translate([0, 0, 1]) sphere(1);");
    render::RenderOptions o;
    o.width = 80, o.height = 60, o.threads = 1, o.aov = render::Aov::Depth;
    const render::Image depth = render::render(s, o);
    int hits = 0, misses = 0;
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 80; ++x) {
            const glm::dvec3 d = through(s.camera, x, y, 80, 60);
            const glm::dvec3 oc = s.camera.position - glm::dvec3(0, 0, 1);
            const double b = glm::dot(oc, d), disc = b * b - (glm::dot(oc, oc) - 1);
            const bool sphere = disc > 1e-6, miss = disc < -1e-6;
            if (sphere) {
                ++hits;
                CHECK(std::isfinite(depth.pixels[y * 80 + x]));
            }
            if (miss) {
                ++misses;
                CHECK(std::isinf(depth.pixels[y * 80 + x]));  // the ground is not a hit
            }
        }
    CHECK(hits > 300);
    o.aov = render::Aov::None;
    o.spp = 1;
    o.alpha = render::Alpha::Straight;
    const render::Image a = render::render(s, o);
    REQUIRE(a.channels == 4);
    int clear = 0;
    for (std::size_t i = 0; i < std::size_t(80 * 60); ++i) clear += a.pixels[i * 4 + 3] == 0;
    CHECK(clear >= misses);  // every pixel off the sphere, the ground's included, is transparent
    CHECK(clear <= 80 * 60 - hits);
}

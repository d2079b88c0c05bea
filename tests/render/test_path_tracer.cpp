// The path tracer (render/integrator_path.hpp) against closed forms:
// - the white furnace: inside a closed diffuse shell of reflectance ρ whose
//   inner surface gives off E, every path collects E·(1 + ρ + … + ρ^D)
//   after at most D bounces, E·(1 − ρ^(D+1))/(1 − ρ) in expectation;
// - direct light on a diffuse plane: a point light of intensity k
//   (inverse square) gives ρ·k·cos β / d², a spherical light of radius r
//   at distance d (its cone of half-angle α, sin α = r/d, wholly above the
//   horizon) ρ·k/d²·cos β·(1 + cos α)/2, the cone's mean cosine. Next-event
//   estimation with MIS, BSDF sampling alone and light sampling alone must
//   each converge to it.
// Tolerances are 4.5 standard errors of the image mean, estimated from the
// spread of the pixels themselves (each an independent mean of spp paths).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "render/render.hpp"
#include "tests/render/same_bytes.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

struct Estimate {
    double mean, error;  // error: 4.5 standard errors of the mean
};

// The mean of channel c over the image and its tolerance.
Estimate image_mean(const render::Image& im, int c) {
    const int n = im.width * im.height;
    double sum = 0, sum2 = 0;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const double v = im.at(x, y, c);
            sum += v;
            sum2 += v * v;
        }
    const double mean = sum / n, var = std::max(0.0, sum2 / n - mean * mean);
    return {mean, 4.5 * std::sqrt(var / (n - 1)) + 1e-6 * std::abs(mean)};
}

render::RenderOptions path_options(int w, int h, int spp) {
    render::RenderOptions o;
    o.width = w;
    o.height = h;
    o.spp = spp;
    o.integrator = render::Integrator::Path;
    o.threads = 2;
    return o;
}

// A diffuse floor (top face z = 0) of reflectance ρ = 0.5, seen from above
// through a 0.4-unit-wide orthographic window centred on `at`; black sky.
csg::Scene floor_scene(const csg::Light& light, glm::dvec3 at) {
    csg::Material m;
    m.color = m.interior = {0.5, 0.5, 0.5};
    m.diffuse = 1;
    csg::Scene s = make_scene(leaf(box({-50, -50, -1}, {50, 50, 0})), {m});
    s.lights = {light};
    s.background = {0, 0, 0};
    look_down(s, at, 10, 0.4);
    return s;
}

// The closed form at each pixel centre of `s`'s 0.4-unit window (the
// radiance varies slowly: the mean over a pixel equals it at the centre to
// far below the noise).
double closed_form_mean(const csg::Scene& s, int w, int h, double (*radiance)(const csg::Light&, glm::dvec3)) {
    double sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::dvec3 p = s.camera.look_at + glm::dvec3((x + 0.5) / w - 0.5, 0.5 - (y + 0.5) / h, 0) * 0.4;
            sum += radiance(s.lights[0], glm::dvec3(p.x, p.y, 0));
        }
    return sum / (w * h);
}

double point_light(const csg::Light& l, glm::dvec3 p) {
    const glm::dvec3 to = l.position - p;
    const double d = glm::length(to);
    return 0.5 * l.intensity / (d * d) * (to.z / d);
}

double sphere_light(const csg::Light& l, glm::dvec3 p) {
    const glm::dvec3 to = l.position - p;
    const double d = glm::length(to), cos_a = std::sqrt(1 - (l.radius / d) * (l.radius / d));
    return 0.5 * l.intensity / (d * d) * (to.z / d) * (1 + cos_a) / 2;
}

csg::Light light_at(glm::dvec3 position, double radius) {
    csg::Light l;
    l.position = position;
    l.intensity = 6;
    l.radius = radius;
    l.inverse_square = true;
    return l;
}

// The white furnace: a shell between radii 1 and 2 of reflectance
// kFurnaceRho glowing with kFurnaceEmission; the camera at the centre sees
// only its inner face (a cut face: the minuend's interior colour).
const glm::dvec3 kFurnaceRho{0.5, 0.65, 0.8}, kFurnaceEmission{0.3, 0.2, 0.1};
csg::Scene furnace() {
    csg::Material m;
    m.color = m.interior = kFurnaceRho;
    m.diffuse = 1;
    m.emission = kFurnaceEmission;
    csg::Scene s = make_scene(op(csg::Op::Difference, {leaf(sphere(2)), leaf(sphere(1))}), {m});
    s.lights.clear();
    s.camera.position = {0, 0, 0};
    s.camera.look_at = {1, 0.2, 0.1};
    s.camera.fov = 90;
    return s;
}

}  // namespace

TEST_CASE("path tracer: the white furnace converges to E (1 - rho^(D+1)) / (1 - rho)", "[render][path]") {
    const glm::dvec3 rho = kFurnaceRho, emission = kFurnaceEmission;
    const csg::Scene s = furnace();
    for (int depth : {16, 3}) {
        render::RenderOptions o = path_options(24, 24, 16);
        o.max_path_depth = depth;
        const render::Image im = render::render(s, o);
        for (int c = 0; c < 3; ++c) {
            const double expected = emission[c] * (1 - std::pow(rho[c], depth + 1)) / (1 - rho[c]);
            const Estimate e = image_mean(im, c);
            INFO("depth " << depth << " channel " << c << ": mean " << e.mean << " ± " << e.error << ", expected " << expected);
            CHECK(std::abs(e.mean - expected) <= e.error);
            CHECK(e.error < 0.05 * expected);  // the test can tell a missing factor apart
        }
    }
}

TEST_CASE("path tracer: a point light on a diffuse plane gives rho k cos(beta) / d^2 exactly", "[render][path]") {
    const csg::Scene s = floor_scene(light_at({0.3, -0.2, 2}, 0), {0.1, 0, 0});
    const render::Image im = render::render(s, path_options(8, 8, 4));
    // No randomness reaches the answer: the one shadow ray per path is
    // deterministic and every bounce escapes to the black sky.
    const double expected = closed_form_mean(s, 8, 8, point_light);
    const Estimate e = image_mean(im, 1);
    CHECK(e.mean == Approx(expected).epsilon(1e-3));
}

TEST_CASE("path tracer: a spherical light on a diffuse plane, MIS, BSDF and light sampling agree with the closed form",
          "[render][path]") {
    const csg::Scene s = floor_scene(light_at({0.3, -0.2, 1}, 0.75), {0.1, 0, 0});
    const double expected = closed_form_mean(s, 16, 16, sphere_light);
    for (auto [lighting, spp] : {std::pair{render::PathLighting::Mis, 64}, std::pair{render::PathLighting::LightOnly, 64},
                                 std::pair{render::PathLighting::BsdfOnly, 256}}) {
        render::RenderOptions o = path_options(16, 16, spp);
        o.path_lighting = lighting;
        const Estimate e = image_mean(render::render(s, o), 0);
        INFO("estimator " << int(lighting) << ": mean " << e.mean << " ± " << e.error << ", closed form " << expected);
        CHECK(std::abs(e.mean - expected) <= e.error);
        CHECK(e.error < 0.1 * expected);
    }
}

TEST_CASE("path tracer: same bytes on 1 and 2 threads, fixed by the seed", "[render][path]") {
    // Glass, a glossy mirror, an emitter, a spherical light and a point
    // light: every kind of bounce.
    csg::Material floor, glass, glossy, lamp;
    glass.transparency = 0.9;
    glass.ior = 1.5;
    glass.absorption = {0.1, 0.2, 0.3};
    glossy.reflect = 0.7;
    glossy.roughness = 0.3;
    lamp.emission = {2, 1.5, 1};
    const Tree t = op(csg::Op::Union, {leaf(box({-5, -5, -1}, {5, 5, 0}, glm::dmat4(1.0), 0)),
                                       leaf(sphere(0.8, translate(-1, 0, 0.8), 1)),
                                       leaf(sphere(0.6, translate(1, 0.5, 0.6), 2)),
                                       leaf(box({-0.3, -0.3, 0}, {0.3, 0.3, 0.4}, translate(0.2, -1.2, 0), 3))});
    csg::Scene s = make_scene(t, {floor, glass, glossy, lamp});
    s.lights.push_back(light_at({2, -3, 4}, 0.5));
    render::RenderOptions o = path_options(40, 30, 4);
    const auto [one, two] = on_1_and_2_threads(s, o);
    CHECK(same_bytes(one, two));
    CHECK(same_bytes(one, render::render(s, o)));
    o.seed = 7;
    CHECK(!same_bytes(one, render::render(s, o)));
}

TEST_CASE("path tracer: passes of 1, 2, 4 ... paths end in the bytes of one pass, and converge", "[render][path]") {
    // The furnace again (depth 16): its exact answer measures each pass.
    const glm::dvec3 rho = kFurnaceRho, emission = kFurnaceEmission;
    const csg::Scene s = furnace();
    const double expected = emission.y * (1 - std::pow(rho.y, 17)) / (1 - rho.y);
    // The root-mean-square error of channel 1 over the pixels.
    auto rmse = [&](const render::Image& im) {
        double sum = 0;
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) sum += std::pow(im.at(x, y, 1) - expected, 2);
        return std::sqrt(sum / (im.width * im.height));
    };
    render::RenderOptions o = path_options(24, 24, 64);
    const render::Image whole = render::render(s, o);
    for (int threads : {1, 2}) {
        std::vector<int> counts;
        std::vector<double> errors;
        o.threads = threads;
        o.on_pass = [&](const render::Image& im, int paths) {
            counts.push_back(paths);
            errors.push_back(rmse(im));
        };
        render::RenderStats stats;
        const render::Image passed = render::render(s, o, &stats);
        CHECK(counts == std::vector<int>{1, 2, 4, 8, 16, 32, 64});
        CHECK(stats.paths_per_pixel == 64);
        CHECK(same_bytes(passed, whole));
        // Noise falls as 1/sqrt(paths): 64 paths have an eighth of one
        // path's error; allow for the spread of 576 pixels.
        REQUIRE(errors.size() == 7);
        CHECK(errors.back() < 0.2 * errors.front());
        CHECK(errors[4] < errors[0]);
    }
    // A time limit already reached: one pass, and the stats say so.
    o.on_pass = nullptr;
    o.time_limit = 1e-9;
    render::RenderStats stats;
    const render::Image quick = render::render(s, o, &stats);
    CHECK(stats.paths_per_pixel == 1);
    CHECK(stats.primary_rays == 24u * 24u);
    CHECK(rmse(quick) > 2 * rmse(whole));
}

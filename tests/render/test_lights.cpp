// Lights beyond the point light: a spherical light's soft shadow against an
// independent Monte-Carlo estimate of the light the occluder leaves, the
// spot's cone by its closed form, inverse-square falloff, shadows = false,
// and the same bytes for any thread count.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

csg::Material matte(double grey) {
    csg::Material m;
    m.color = m.interior = glm::dvec3(grey);
    m.specular = 0;
    m.diffuse = 1;
    return m;
}

// Ground z <= 0 (albedo 0.5) with an occluding ball of radius 1 at `ball`,
// seen straight down by an orthographic camera 8 wide in 41 pixels.
csg::Scene ground_scene(glm::dvec3 ball) {
    const Tree t = op(Op::Union, {leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0}, glm::dmat4(1.0), 0)),
                                  leaf(sphere(1, translate(ball.x, ball.y, ball.z), 0))});
    csg::Scene s = make_scene(t, {matte(0.5)});
    s.camera.position = {0, -0.001, 10};
    s.camera.look_at = {0, 0, 0};
    s.camera.up = {0, 1, 0};
    s.camera.orthographic = true;
    s.camera.height = 8;
    return s;
}

render::RenderOptions centres() {
    render::RenderOptions o;
    o.width = o.height = 41;  // pixel i's centre is x = ((i + 0.5) / 41 - 0.5) · 8
    o.threads = 1;
    return o;
}
double ground_x(int i) { return ((i + 0.5) / 41 - 0.5) * 8; }

// The independent estimate: the mean of n·l over directions uniform in the
// cone the light sphere fills, zero where the ray meets the ball first
// (a plain ray–sphere test, not kerf's code).
double lit_fraction(glm::dvec3 p, glm::dvec3 light, double r, glm::dvec3 ball, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    const glm::dvec3 axis = glm::normalize(light - p);
    const double d = glm::length(light - p), cos_max = std::sqrt(1 - r * r / (d * d));
    const glm::dvec3 t = glm::normalize(glm::cross(axis, glm::dvec3(0, 1, 0))), b = glm::cross(axis, t);
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double c = 1 - u(rng) * (1 - cos_max), s = std::sqrt(1 - c * c), phi = 2 * M_PI * u(rng);
        const glm::dvec3 dir = c * axis + s * (std::cos(phi) * t + std::sin(phi) * b);
        const glm::dvec3 oc = p - ball;
        const double bq = glm::dot(oc, dir), disc = bq * bq - (glm::dot(oc, oc) - 1);
        const bool blocked = disc > 0 && -bq - std::sqrt(disc) > 0;
        if (!blocked) sum += std::max(0.0, dir.z);  // the ground's normal is +z
    }
    return sum / n;
}

// The soft-shadow estimates' set-up: the ball at soft_ball, a light sphere
// of radius 1 and intensity 0.8 at soft_centre, `samples` shadow rays.
const glm::dvec3 soft_ball(2, 0, 2), soft_centre(5, 0, 5);
csg::Scene soft_shadow_scene(std::uint32_t samples) {
    csg::Scene s = ground_scene(soft_ball);
    csg::Light light;
    light.position = soft_centre;
    light.radius = 1;
    light.samples = samples;
    light.intensity = 0.8;
    s.lights = {light};
    return s;
}

}  // namespace

TEST_CASE("a spherical light's soft shadow matches a Monte-Carlo estimate", "[render][lights]") {
    const glm::dvec3 ball = soft_ball, centre = soft_centre;
    csg::Scene s = soft_shadow_scene(4096);
    const csg::Light light = s.lights[0];
    const render::Image im = render::render(s, centres());
    std::mt19937_64 rng(3);
    int partial = 0;
    for (int i = 0; i < 41; i += 2) {
        const glm::dvec3 p(ground_x(i), 0, 0);
        if (glm::length(glm::dvec2(p.x - ball.x, p.y - ball.y)) < 1.05) continue;  // the ball itself is seen there
        const double f = lit_fraction(p, centre, light.radius, ball, rng);
        INFO("x = " << p.x << ", lit fraction " << f);
        CHECK(im.at(i, 20, 0) == Approx(0.5 * (0.1 + 0.8 * f)).margin(4e-3));
        const double peak = glm::normalize(centre - p).z;
        partial += f > 0.1 * peak && f < 0.9 * peak;
    }
    CHECK(partial >= 2);  // the row crosses the penumbra, not only umbra and light

    // shadows = false: the same points get the unshadowed light.
    s.lights[0].shadows = false;
    const render::Image open = render::render(s, centres());
    const glm::dvec3 p(ground_x(4), 0, 0);
    CHECK(open.at(4, 20, 0) > im.at(4, 20, 0) + 0.05);
    CHECK(open.at(4, 20, 0) == Approx(0.5 * (0.1 + 0.8 * lit_fraction(p, centre, 1, {0, 0, -100}, rng))).margin(4e-3));
}

TEST_CASE("a spot lights its cone, fades over the falloff, and leaves the rest dark", "[render][lights]") {
    csg::Scene s = ground_scene({0, 0, -50});  // the ball out of the way, under the ground
    csg::Light spot;
    spot.spot = true;
    spot.position = {0, 0, 4};
    spot.direction = {0, 0, -1};
    spot.spot_angle = 20;
    spot.spot_falloff = 20;
    s.lights = {spot};
    const render::Image im = render::render(s, centres());
    for (int i = 20; i < 41; ++i) {
        const double x = ground_x(i), angle = std::atan2(std::abs(x), 4.0) * 180 / M_PI;
        const double ndl = 4 / std::hypot(x, 4.0);
        double k = angle <= 20 ? 1 : 0;
        if (angle > 20 && angle < 40) {
            const double t = (40 - angle) / 20;
            k = t * t * (3 - 2 * t);
        }
        INFO("x = " << x << ", " << angle << " degrees off the axis");
        CHECK(im.at(i, 20, 0) == Approx(0.5 * (0.1 + k * ndl)).epsilon(1e-5));
    }
}

TEST_CASE("inverse-square attenuation divides by the distance squared", "[render][lights]") {
    csg::Scene s = ground_scene({0, 0, -50});
    csg::Light l;
    l.position = {0, 0, 3};
    l.intensity = 9;
    l.inverse_square = true;
    s.lights = {l};
    const render::Image im = render::render(s, centres());
    for (int i : {20, 26, 33, 40}) {
        const double x = ground_x(i), d2 = x * x + 9;
        CHECK(im.at(i, 20, 0) == Approx(0.5 * (0.1 + 9 / d2 * 3 / std::sqrt(d2))).epsilon(1e-5));
    }
}

TEST_CASE("soft shadows are the same bytes for any thread count", "[render][lights]") {
    csg::Scene s = ground_scene({1, 0, 2});
    csg::Light l;
    l.position = {4, 1, 5};
    l.radius = 1.5;
    l.samples = 9;  // few samples: noisy, so an order-dependent generator would show
    s.lights = {l};
    render::RenderOptions o = centres();
    o.width = o.height = 96;
    o.adaptive = true;
    const render::Image one = render::render(s, o);
    o.threads = 2;
    const render::Image two = render::render(s, o);
    REQUIRE(one.pixels.size() == two.pixels.size());
    CHECK(std::equal(one.pixels.begin(), one.pixels.end(), two.pixels.begin()));
}

TEST_CASE("a probing light (the studio key) is exact in light and umbra, near the estimate in the penumbra, and cheaper", "[render][lights]") {
    const glm::dvec3 ball = soft_ball, centre = soft_centre;
    csg::Scene s = soft_shadow_scene(16);
    const csg::Light light = s.lights[0];
    render::RenderStats all_stats, probe_stats;
    const render::Image all = render::render(s, centres(), &all_stats);
    s.lights[0].probe = true;
    const render::Image probed = render::render(s, centres(), &probe_stats);
    CHECK(probe_stats.shadow_rays < all_stats.shadow_rays);  // lit and umbra points: 5 rays, not 16
    std::mt19937_64 rng(5);
    double err_all = 0, err_probed = 0;
    int n = 0, partial = 0;
    for (int i = 0; i < 41; ++i) {
        const glm::dvec3 p(ground_x(i), 0, 0);
        if (glm::length(glm::dvec2(p.x - ball.x, p.y - ball.y)) < 1.05) continue;  // the ball itself is seen there
        const double f = lit_fraction(p, centre, light.radius, ball, rng);
        const double expected = 0.5 * (0.1 + 0.8 * f), peak = glm::normalize(centre - p).z;
        INFO("x = " << p.x << ", lit fraction " << f);
        if (f == 0 || f > 0.999 * lit_fraction(p, centre, light.radius, {0, 0, -100}, rng))
            CHECK(probed.at(i, 20, 0) == all.at(i, 20, 0));  // umbra or full light: the 16 rays' value
        CHECK(probed.at(i, 20, 0) == Approx(expected).margin(0.5 * 0.8 * peak * 6 / 16));  // within 6 of the 16 rays
        partial += f > 0.1 * peak && f < 0.9 * peak;
        err_all += std::pow(all.at(i, 20, 0) - expected, 2);
        err_probed += std::pow(probed.at(i, 20, 0) - expected, 2);
        ++n;
    }
    CHECK(partial >= 2);
    INFO("RMS: 16 rays " << std::sqrt(err_all / n) << ", probed " << std::sqrt(err_probed / n));
    CHECK(err_probed <= 4 * err_all + 1e-6);  // RMS at most twice the 16 rays' (measured: 1.5×)
}

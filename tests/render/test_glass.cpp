// Glass against closed forms (docs/language.md, "Glass"): Fresnel's
// reflectance at normal incidence, at Brewster's angle and about the
// critical angle; a ray through a glass sphere against the analytic path
// (exit point, direction, the transmitted share); total internal
// reflection in a right-angle prism; Beer–Lambert absorption through a
// slab, for camera and shadow rays; the same bytes for any thread count.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "render/optics.hpp"
#include "render/render.hpp"
#include "render/shading.hpp"
#include "tests/render/same_bytes.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Textbook Fresnel in angles (Born & Wolf): rs = −sin(θi−θt)/sin(θi+θt),
// rp = tan(θi−θt)/tan(θi+θt), from n1 into n2.
double fresnel_angles(double theta_i, double n1, double n2) {
    const double theta_t = std::asin(n1 / n2 * std::sin(theta_i));
    const double rs = -std::sin(theta_i - theta_t) / std::sin(theta_i + theta_t);
    const double rp = std::tan(theta_i - theta_t) / std::tan(theta_i + theta_t);
    return 0.5 * (rs * rs + rp * rp);
}

csg::Material glass(double ior, glm::dvec3 absorption = glm::dvec3(0)) {
    csg::Material m;
    m.transparency = 1;
    m.ior = ior;
    m.absorption = absorption;
    m.diffuse = m.specular = 0;
    m.color = m.interior = glm::dvec3(0);
    return m;
}

csg::Material glow() {  // shows its emission and nothing else
    csg::Material m;
    m.color = m.interior = glm::dvec3(0);
    m.diffuse = m.specular = 0;
    m.emission = glm::dvec3(1);
    return m;
}

// A scene without lights on a black background: only emitters are seen.
csg::Scene dark(const Tree& t, std::vector<csg::Material> mats) {
    csg::Scene s = make_scene(t, std::move(mats));
    s.lights.clear();
    s.background = glm::dvec3(0);
    return s;
}

glm::dvec3 trace(const csg::Scene& s, glm::dvec3 o, glm::dvec3 d, int depth = 8) {
    const render::CsgTracer tracer(s, false);
    const render::Shader shader(s, tracer, depth);
    render::ThreadState ts;
    return shader.radiance(render::TraceRay{o, glm::normalize(d), 0, kInf}, 0, ts);
}

}  // namespace

TEST_CASE("Fresnel reflectance at normal incidence, Brewster's angle and the critical angle", "[render][glass]") {
    for (double n : {1.33, 1.5, 2.4}) {
        double cos_t;
        const double r0 = (n - 1) / (n + 1) * (n - 1) / (n + 1);
        CHECK(render::fresnel_dielectric(1, 1 / n, cos_t) == Approx(r0).epsilon(1e-12));
        CHECK(cos_t == Approx(1));
        CHECK(render::fresnel_dielectric(1, n, cos_t) == Approx(r0).epsilon(1e-12));  // from inside: the same
        // Brewster: p-polarised light is not reflected, so R = rs²/2 with
        // rs = (1 − n²)/(1 + n²).
        const double brewster = std::atan(n);
        const double rs = (1 - n * n) / (1 + n * n);
        CHECK(render::fresnel_dielectric(std::cos(brewster), 1 / n, cos_t) == Approx(0.5 * rs * rs).epsilon(1e-10));
        // Any angle, both ways, against the angle form.
        for (double deg : {10.0, 30.0, 60.0, 85.0}) {
            const double th = deg * M_PI / 180;
            CHECK(render::fresnel_dielectric(std::cos(th), 1 / n, cos_t) == Approx(fresnel_angles(th, 1, n)).epsilon(1e-9));
            CHECK(cos_t == Approx(std::cos(std::asin(std::sin(th) / n))).epsilon(1e-12));
        }
        // From inside: total internal reflection from asin(1/n) on.
        const double critical = std::asin(1 / n);
        CHECK(render::fresnel_dielectric(std::cos(critical + 1e-7), n, cos_t) == 1.0);
        CHECK(cos_t == 0.0);
        const double below = render::fresnel_dielectric(std::cos(critical - 1e-3), n, cos_t);
        CHECK(below < 1.0);
        CHECK(below == Approx(fresnel_angles(critical - 1e-3, n, 1)).epsilon(1e-9));
        CHECK(render::fresnel_dielectric(std::cos(critical * 0.5), n, cos_t) ==
              Approx(fresnel_angles(critical * 0.5, n, 1)).epsilon(1e-9));
    }
}

TEST_CASE("Snell's law: n1 sin θ1 = n2 sin θ2, in the plane of incidence", "[render][glass]") {
    const glm::dvec3 n(0, 0, 1);
    for (double deg : {0.0, 20.0, 45.0, 70.0}) {
        const double th = deg * M_PI / 180;
        const glm::dvec3 d(std::sin(th), 0, -std::cos(th));
        double cos_t;
        render::fresnel_dielectric(std::cos(th), 1 / 1.5, cos_t);
        const glm::dvec3 t = render::refract_direction(d, n, 1 / 1.5, std::cos(th), cos_t);
        CHECK(glm::length(t) == Approx(1));
        CHECK(t.y == 0.0);
        CHECK(t.z < 0);
        CHECK(1.5 * t.x == Approx(std::sin(th)).margin(1e-12));
    }
}

TEST_CASE("a ray through a glass sphere follows the analytic path", "[render][glass]") {
    // Unit sphere of index n; a ray along +z at height b enters at angle
    // θi = asin b, runs at θt = asin(b/n) and leaves at polar angle 2θt − θi
    // from +z, turned by δ = 2(θi − θt) towards the axis. A small emitter
    // 10 units along the analytic exit ray is seen with the share
    // (1 − R)² the two surfaces let through (R the same both ways), times
    // exp(−σ·2cos θt) inside; moved off the path by 0.15 it is missed.
    const double n = 1.5;
    for (double b : {0.0, 0.3, 0.6, 0.8}) {
        const double ti = std::asin(b), tt = std::asin(b / n), delta = 2 * (ti - tt);
        const glm::dvec3 exit(std::sin(2 * tt - ti), 0, std::cos(2 * tt - ti));
        const glm::dvec3 out(-std::sin(delta), 0, std::cos(delta));
        const double r = fresnel_angles(std::max(ti, 1e-9), 1, n);
        const glm::dvec3 sigma(0.0, 0.2, 0.7);
        for (double miss : {0.0, 0.15}) {
            const glm::dvec3 target = exit + 10.0 * out + glm::dvec3(0, miss, 0);
            const Tree t = op(Op::Union, {leaf(sphere(1, glm::dmat4(1.0), 0)),
                                          leaf(sphere(0.05, translate(target.x, target.y, target.z), 1))});
            const csg::Scene s = dark(t, {glass(n, sigma), glow()});
            // Depth 1: the refraction in, no internal reflection after it.
            const glm::dvec3 c = trace(s, {b, 0, -5}, {0, 0, 1}, 1);
            INFO("b = " << b << ", off the path by " << miss);
            for (int k = 0; k < 3; ++k) {
                const double expected = miss > 0 ? 0.0 : (1 - r) * (1 - r) * std::exp(-sigma[k] * 2 * std::cos(tt));
                CHECK(c[k] == Approx(expected).epsilon(1e-9).margin(1e-12));
            }
            if (b == 0 && miss == 0) {
                // On the axis every second internal reflection leaves towards
                // the emitter too: depth 7 allows 6 of them, 3 round trips,
                // the geometric series (R² e^(−2σL))^k for k = 0..3.
                const glm::dvec3 deep = trace(s, {b, 0, -5}, {0, 0, 1}, 7);
                for (int k = 0; k < 3; ++k) {
                    const double once = std::exp(-sigma[k] * 2), bounce = r * r * once * once;
                    const double expected = (1 - r) * (1 - r) * once * (1 + bounce + bounce * bounce + bounce * bounce * bounce);
                    CHECK(deep[k] == Approx(expected).epsilon(1e-9));
                }
            }
        }
    }
}

TEST_CASE("total internal reflection in a right-angle prism", "[render][glass]") {
    // The box [-1, 1]³ cut by x + z <= 0. A ray up at x = −0.5 enters the
    // bottom face square on, meets the hypotenuse at 45°, beyond the
    // critical angle of n = 1.5 (41.8°): all of it turns to −x and leaves
    // through the face x = −1 square on, towards an emitter. Transmitted:
    // (1 − R0)² with R0 = ((n−1)/(n+1))². Below the critical angle (n =
    // 1.3, 50.3°) the hypotenuse reflects only Fresnel's share.
    for (double n : {1.5, 1.3}) {
        const Tree t = op(Op::Union, {op(Op::Intersection, {leaf(box({-1, -1, -1}, {1, 1, 1}, glm::dmat4(1.0), 0)),
                                                              leaf(make_leaf(csg::PrimKind::Plane,
                                                                             {std::sqrt(0.5), 0, std::sqrt(0.5), 0},
                                                                             glm::dmat4(1.0), 0))}),
                                      leaf(sphere(0.1, translate(-5, 0, 0.5), 1))});
        const csg::Scene s = dark(t, {glass(n), glow()});
        const double r0 = (n - 1) / (n + 1) * (n - 1) / (n + 1);
        const double hyp = n < std::sqrt(2.0) ? fresnel_angles(M_PI / 4, n, 1) : 1.0;
        INFO("n = " << n);
        // Depth 2: in, one reflection inside (the hypotenuse), no more.
        CHECK(trace(s, {-0.5, 0, -5}, {0, 0, 1}, 2).x == Approx((1 - r0) * (1 - r0) * hyp).epsilon(1e-9));
    }
}

TEST_CASE("Beer–Lambert absorption through a slab, for camera and shadow rays", "[render][glass]") {
    // A clear slab 0.7 thick (ior 1: no refraction, no reflection).
    const double d = 0.7;
    const glm::dvec3 sigma(0.1, 1.0, 3.0);
    csg::Material slab = glass(1, sigma);
    const Tree t = op(Op::Union, {leaf(box({-1, -1, 1}, {1, 1, 1 + d}, glm::dmat4(1.0), 0)),
                                  leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0}, glm::dmat4(1.0), 1))});
    csg::Material floor;
    floor.color = floor.interior = glm::dvec3(0.5);
    floor.diffuse = 1;
    floor.specular = 0;
    csg::Scene s = make_scene(t, {slab, floor});
    s.background = {0.3, 0.6, 0.9};
    s.lights = {csg::Light{true, {}, {0, 0, -1}, {1, 1, 1}, 1}};
    // Looking down through the slab at the background side: up from below.
    const glm::dvec3 up = trace(s, {0, 0, 0.5}, {0, 0, 1});
    for (int k = 0; k < 3; ++k) CHECK(up[k] == Approx(s.background[k] * std::exp(-sigma[k] * d)).epsilon(1e-12));
    // The floor below the slab: ambient + Lambert through the slab,
    // transparency · exp(−σd) of the light (a filtered shadow).
    for (double tr : {1.0, 0.6}) {
        s.materials[0].transparency = tr;
        const glm::dvec3 c = trace(s, {0, 0.2, 0.5}, {0, 0, -1});
        for (int k = 0; k < 3; ++k) CHECK(c[k] == Approx(0.5 * (0.1 + tr * std::exp(-sigma[k] * d))).epsilon(1e-12));
    }
    s.materials[0].transparency = 0;  // opaque: the full shadow
    CHECK(trace(s, {0, 0.2, 0.5}, {0, 0, -1}).x == Approx(0.05).epsilon(1e-12));
}

TEST_CASE("glass, glossy and glowing surfaces give the same bytes for any thread count", "[render][glass]") {
    csg::Material shiny;
    shiny.reflect = 0.6;
    shiny.roughness = 0.3;
    shiny.color = shiny.interior = {0.8, 0.7, 0.2};
    csg::Material lamp = glow();
    lamp.emission = {2, 1.5, 1};
    const Tree t = op(Op::Union, {leaf(sphere(1, translate(0, 0, 1), 0)), leaf(sphere(0.5, translate(1.6, 0.5, 0.5), 2)),
                                  leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0}, glm::dmat4(1.0), 1))});
    csg::Material g = glass(1.5, {0.1, 0.3, 0.5});
    g.specular = 0.5;
    csg::Scene s = make_scene(t, {g, shiny, lamp});
    render::RenderOptions o;
    o.width = 64;
    o.height = 48;
    o.spp = 4;
    const auto [one, two] = on_1_and_2_threads(s, o);
    CHECK(same_bytes(one, two));
    // The glass is not opaque: its centre differs from an opaque ball's.
    s.materials[0].transparency = 0;
    const render::Image opaque = render::render(s, o);
    CHECK(!same_bytes(opaque, one));
}

TEST_CASE("an emitter shows its emission on top of its shading", "[render][glass]") {
    csg::Material m = glow();
    m.color = m.interior = {0.5, 0.5, 0.5};
    m.emission = {0.2, 0.4, 0.6};
    csg::Scene s = dark(leaf(sphere(1, glm::dmat4(1.0), 0)), {m});
    const glm::dvec3 c = trace(s, {0, -5, 0}, {0, 1, 0});
    for (int k = 0; k < 3; ++k) CHECK(c[k] == Approx(0.1 * 0.5 + m.emission[k]).epsilon(1e-12));
}

// A glass half-space (an unbounded solid): a ray refracted into it never
// leaves; it is a miss seen through infinite glass, not a trace from a
// point at infinity (that aborted in Embree's ray check, a fuzz find). From
// above along the normal: Fresnel's f of the background mirrored, the rest
// through the glass, all of it in a clear channel and none in an
// absorbing one.
TEST_CASE("a ray refracted into an unbounded glass solid sees the background through it", "[render][glass]") {
    const glm::dvec3 sigma(0, 0.5, 0);
    // Beside it, a ring of small opaque balls high above, off every ray
    // the check below traces: enough units for the tracer's top BVH, which
    // is where a ray from infinity aborted (a scene of a few units is
    // walked without Embree).
    std::vector<Tree> parts{leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0}, glm::dmat4(1.0), 0))};
    for (int i = 0; i < 40; ++i)
        parts.push_back(leaf(sphere(0.2, translate(8 * std::cos(0.157 * i), 8 * std::sin(0.157 * i), 6), 1)));
    const Tree t = op(Op::Union, parts);
    csg::Material white;
    white.color = white.interior = glm::dvec3(1);
    csg::Scene s = dark(t, {glass(1.5, sigma), white});
    s.background = {0.3, 0.6, 0.9};
    const double f = 0.04;  // ((1.5 − 1) / (1.5 + 1))²
    const glm::dvec3 c = trace(s, {0.1, 0.2, 1}, {0, 0, -1});
    CHECK(c.x == Approx(s.background.x).epsilon(1e-9));
    CHECK(c.y == Approx(f * s.background.y).epsilon(1e-9));
    CHECK(c.z == Approx(s.background.z).epsilon(1e-9));
    // Whole renders, both integrators, the camera above the glass and
    // inside it: finite pixels, no abort.
    for (const glm::dvec3& eye : {glm::dvec3(3, -4, 2), glm::dvec3(0.5, -1, -2)})
        for (render::Integrator integrator : {render::Integrator::Whitted, render::Integrator::Path}) {
            s.camera.position = eye;
            s.camera.look_at = {0, 0, 0};
            render::RenderOptions o;
            o.width = 16;
            o.height = 12;
            o.integrator = integrator;
            const render::Image image = render::render(s, o);
            for (float v : image.pixels) REQUIRE(std::isfinite(v));
        }
}

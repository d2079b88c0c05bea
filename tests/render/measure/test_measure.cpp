// kerf measure against closed forms: volumes, areas and centroids of solids
// whose values are known exactly, at tiny, unit and huge scales and far from
// the origin; the reported error must cover the true error.
#include <catch2/catch.hpp>

#include <cmath>

#include "render/measure/measure.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

constexpr double kPi = 3.14159265358979323846;

render::Measurement run(const csg::Scene& s, int resolution = 256, int threads = 0) {
    render::MeasureOptions o;
    o.resolution = resolution;
    o.threads = threads;
    return render::measure(s, o);
}

// |got − exact| is within the reported error and the relative error is small.
void check(double got, double error, double exact, double rel) {
    INFO("got " << got << " ± " << error << ", exact " << exact);
    CHECK(std::abs(got - exact) <= std::max(error, 1e-12 * std::abs(exact)));
    CHECK(std::abs(got - exact) <= rel * std::abs(exact));
}

}  // namespace

TEST_CASE("measure: a sphere at every scale and far from the origin", "[measure]") {
    for (double r : {1e-6, 1.0, 1e6}) {
        for (double far : {0.0, 1e4}) {
            const glm::dvec3 c(3 * r + far, -2 * r, r + far);
            const auto m = run(make_scene(leaf(sphere(r, translate(c.x, c.y, c.z)))));
            INFO("r = " << r << ", offset " << far);
            REQUIRE_FALSE(m.empty);
            check(m.volume, m.volume_error, 4.0 / 3.0 * kPi * r * r * r, 1e-3);
            check(m.area, m.area_error, 4 * kPi * r * r, 2e-3);
            for (int k = 0; k < 3; ++k) CHECK(std::abs(m.centroid[k] - c[k]) <= 1e-6 * r + 1e-12 * std::abs(c[k]));
            for (int k = 0; k < 3; ++k) {
                CHECK(m.bounds.lo[k] == Approx(c[k] - r).margin(1e-3 * r));
                CHECK(m.bounds.hi[k] == Approx(c[k] + r).margin(1e-3 * r));
            }
        }
    }
}

TEST_CASE("measure: torus volume 2π²Rr² and area 4π²Rr", "[measure]") {
    const double R = 2, r = 0.5;
    const auto m = run(make_scene(leaf(make_leaf(csg::PrimKind::Torus, {R, r}, rotate_deg(30, {1, 1, 0})))));
    check(m.volume, m.volume_error, 2 * kPi * kPi * R * r * r, 2e-3);
    check(m.area, m.area_error, 4 * kPi * kPi * R * r, 3e-3);
    for (int k = 0; k < 3; ++k) CHECK(std::abs(m.centroid[k]) < 1e-3);
}

TEST_CASE("measure: a rotated box and a frustum with its centroid", "[measure]") {
    SECTION("box") {
        const auto m = run(make_scene(leaf(box({0, 0, 0}, {1, 2, 3}, rotate_deg(37, {0.3, 1, 0.2}) * translate(5, 0, 0)))));
        check(m.volume, m.volume_error, 6, 1e-3);
        check(m.area, m.area_error, 22, 2e-3);
    }
    SECTION("frustum") {
        // Radii 2 at z = 0 and 1 at z = 3: V = πh(R² + Rr + r²)/3; centroid
        // z = h(R² + 2Rr + 3r²)/(4(R² + Rr + r²)); area of the sides
        // π(R + r)·slant plus both discs.
        const double R = 2, r = 1, h = 3;
        const auto m = run(make_scene(leaf(make_leaf(csg::PrimKind::Cylinder, {0, h, R, r}))));
        check(m.volume, m.volume_error, kPi * h * (R * R + R * r + r * r) / 3, 1e-3);
        check(m.area, m.area_error, kPi * (R + r) * std::hypot(R - r, h) + kPi * (R * R + r * r), 2e-3);
        CHECK(m.centroid.z == Approx(h * (R * R + 2 * R * r + 3 * r * r) / (4 * (R * R + R * r + r * r))).epsilon(1e-4));
        CHECK(m.bounds.lo.z == Approx(0).margin(1e-9));
        CHECK(m.bounds.hi.z == Approx(h).margin(1e-9));
    }
}

TEST_CASE("measure: CSG counts shared volume once and cut faces as surface", "[measure]") {
    SECTION("union of two overlapping spheres") {
        // Each sphere r, centres d apart: the lens they share has volume
        // π(4r + d)(2r − d)²/12; each loses a cap of height h = r − d/2.
        const double r = 1, d = 1.2, h = r - d / 2;
        const auto m = run(make_scene(op(Op::Union, {leaf(sphere(r)), leaf(sphere(r, translate(d, 0, 0)))})));
        check(m.volume, m.volume_error, 2 * 4.0 / 3.0 * kPi - kPi * (4 * r + d) * (2 * r - d) * (2 * r - d) / 12, 1e-3);
        check(m.area, m.area_error, 2 * (4 * kPi * r * r - 2 * kPi * r * h), 2e-3);
        CHECK(m.centroid.x == Approx(d / 2).epsilon(1e-4));
    }
    SECTION("a box minus a sphere that pokes out of one face") {
        // Box [-2,2]³ minus a sphere of radius 1 centred on the face x = 2:
        // half the ball is removed, the face loses a disc and gains a
        // hemisphere.
        const auto m = run(make_scene(op(Op::Difference, {leaf(box({-2, -2, -2}, {2, 2, 2})), leaf(sphere(1, translate(2, 0, 0)))})));
        check(m.volume, m.volume_error, 64 - 2.0 / 3.0 * kPi, 1e-3);
        check(m.area, m.area_error, 96 - kPi + 2 * kPi, 2e-3);
        // Moment: the box's is 0, the removed half ball's x moment is
        // (2π/3)·(2 + 3/8) about x = 2 shifted: x̄ = 2 − 3/8.
        const double v_half = 2.0 / 3.0 * kPi;
        CHECK(m.centroid.x == Approx(-(v_half * (2 - 3.0 / 8)) / (64 - v_half)).epsilon(1e-3));
    }
}

TEST_CASE("measure: the same numbers for any thread count, the error shrinks with resolution", "[measure]") {
    const csg::Scene s = make_scene(op(Op::Difference, {leaf(sphere(1.3)), leaf(box({-2, -2, -0.2}, {2, 2, 0.3}, rotate_deg(20, {1, 0, 0})))}));
    const auto a = run(s, 128, 1), b = run(s, 128, 2);
    CHECK(a.volume == b.volume);
    CHECK(a.area == b.area);
    CHECK(a.centroid == b.centroid);
    const csg::Scene ball = make_scene(leaf(sphere(1)));
    const auto coarse = run(ball, 32), fine = run(ball, 512);
    CHECK(fine.volume_error < coarse.volume_error / 4);
    CHECK(std::abs(fine.volume - 4.0 / 3.0 * kPi) < std::abs(coarse.volume - 4.0 / 3.0 * kPi));
}

TEST_CASE("measure: unbounded, empty and bad resolutions", "[measure]") {
    CHECK_THROWS_AS(run(make_scene(leaf(make_leaf(csg::PrimKind::Plane, {0, 0, 1, 0})))), std::runtime_error);
    for (int bad : {0, 7, 9, 100001}) CHECK_THROWS_AS(run(make_scene(leaf(sphere(1))), bad), std::invalid_argument);
    csg::Scene none;
    CHECK(run(none).empty);
    // Two disjoint boxes intersected: nothing.
    const auto m = run(make_scene(op(Op::Intersection, {leaf(box({0, 0, 0}, {1, 1, 1})), leaf(box({2, 0, 0}, {3, 1, 1}))})));
    CHECK(m.empty);
    CHECK(m.volume == 0);
}

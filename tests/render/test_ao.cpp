// Ambient occlusion against a closed form (render/ao.hpp): a point on a
// floor at distance d from a wall (the half-space x > d) sees the wall along
// every direction whose x-component exceeds c = d/R within reach R. Under a
// cosine-weighted hemisphere the directions' (x, y) are uniform over the
// unit disk (Malley), so the blocked share is the disk segment x > c over
// π: (acos c − c·√(1 − c²))/π, and the visible share 1 minus that (½ for an
// unbounded reach, 1 for c ≥ 1).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include "render/ao.hpp"
#include "render/lights.hpp"
#include "tests/render/same_bytes.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;

namespace {

double visible_share(double c) {
    if (c >= 1) return 1;
    return 1 - (std::acos(c) - c * std::sqrt(1 - c * c)) / std::numbers::pi;
}

}  // namespace

TEST_CASE("ambient occlusion beside a wall: the cosine-weighted visible share in closed form", "[render][ao]") {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    const double d = 1;
    // Floor z ≤ 0 and wall x ≥ d, both far larger than any reach used.
    const Tree t = op(csg::Op::Union, {leaf(box({-1e4, -1e4, -1}, {1e4, 1e4, 0})), leaf(box({d, -1e4, -1}, {1e4, 1e4, 1e4}))});
    const csg::Scene s = make_scene(t);
    const render::CsgTracer tracer(s, false);
    render::TraceScratch scratch;
    for (double reach : {kInf, 4.0, 2.0, 1.25, 0.5}) {
        const double c = reach == kInf ? 0 : d / reach;
        const double want = visible_share(c);
        // 64 points along the wall, 1024 stratified samples each: the mean's
        // standard error is below √(p(1−p)/65536) ≤ 0.002; 4σ allowed.
        const render::SamplePattern pattern(1024);
        double sum = 0;
        std::uint64_t rays = 0;
        for (int k = 0; k < 64; ++k) {
            const glm::dvec3 o{0, k * 0.37 - 12, 1e-7};
            sum += render::ambient_visibility(tracer, o, {0, 0, 1}, reach, pattern, render::shading_rng(o, 7), scratch, rays);
        }
        INFO("reach " << reach << " want " << want);
        CHECK(rays == 64u * 1024u);
        CHECK(sum / 64 == Approx(want).margin(0.008));
        // One point alone at 1024 samples: within 4 binomial σ.
        const glm::dvec3 o{0, 0, 1e-7};
        const double one = render::ambient_visibility(tracer, o, {0, 0, 1}, reach, pattern, render::shading_rng(o, 7), scratch, rays);
        CHECK(one == Approx(want).margin(4 * std::sqrt(want * (1 - want) / 1024) + 1e-9));
        // Seeded: the same point gives the same estimate.
        CHECK(render::ambient_visibility(tracer, o, {0, 0, 1}, reach, pattern, render::shading_rng(o, 7), scratch, rays) == one);
    }
    // Far from the wall nothing is within reach; any normal works (the frame about n).
    const glm::dvec3 far{-50, 0, 1e-7};
    std::uint64_t rays = 0;
    CHECK(render::ambient_visibility(tracer, far, {0, 0, 1}, 10, render::SamplePattern(64), 1, scratch, rays) == 1);
    const glm::dvec3 on_wall{d - 1e-7, 0, 5};  // the wall's face, normal −x: the floor blocks below reach
    const double v = render::ambient_visibility(tracer, on_wall, {-1, 0, 0}, kInf, render::SamplePattern(4096), 3, scratch, rays);
    CHECK(v == Approx(0.5).margin(0.04));
}

TEST_CASE("ambient occlusion in a render: ambient dimmed by the closed-form share, same bytes on any thread count", "[render][ao]") {
    // Floor seen from above, no lights: colour = 0.1 × albedo × visible share.
    const Tree t = op(csg::Op::Union, {leaf(box({-1e3, -1e3, -1}, {1e3, 1e3, 0})), leaf(box({1, -1e3, -1}, {1e3, 1e3, 1e3}))});
    csg::Scene s = make_scene(t);
    s.lights.clear();
    s.ambient_occlusion = {256, 2.0};
    look_down(s, {0, 0, 0}, 0.5, 0.01);
    render::RenderOptions o;
    o.width = o.height = 4;
    const auto [one, two] = on_1_and_2_threads(s, o);
    CHECK(same_bytes(one, two));
    double mean = 0;
    for (int i = 0; i < 16; ++i) mean += one.pixels[i * 3] / 16.0;
    // Distance 1 from the wall, reach 2: c = ½; 16 points × 256 samples.
    CHECK(mean / (0.1 * 0.8) == Approx(visible_share(0.5)).margin(0.02));
}

// CsgTracer::misses_all culls whole image tiles; it must never cull a tile
// one of whose rays hits the solid. Random quads of rays around a few
// solids, pinhole and orthographic: whenever a quad is culled, rays mixed
// from its corners (convex combinations, as a tile's pixels are) all miss
// by intersect(); and culling must happen often, or it saves nothing.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "render/tracer/tracer.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

// Whether intersect() misses every one of `samples` rays of the quad: its
// four corners, then bilinear mixes of them (as a tile's pixels are).
template <typename Rng>
int hits_in_quad(const render::CsgTracer& tracer, render::TraceScratch& scratch, const glm::dvec3 (&o)[4],
                 const glm::dvec3 (&d)[4], int samples, Rng& rng) {
    std::uniform_real_distribution<double> w(0, 1);
    const double sx[4] = {0, 1, 1, 0}, sy[4] = {0, 0, 1, 1};
    int hits = 0;
    for (int k = 0; k < samples; ++k) {
        const double a = k < 4 ? sx[k] : w(rng), b = k < 4 ? sy[k] : w(rng);
        const double wt[4] = {(1 - a) * (1 - b), a * (1 - b), a * b, (1 - a) * b};
        glm::dvec3 ro(0.0), rd(0.0);
        for (int i = 0; i < 4; ++i) ro += wt[i] * o[i], rd += wt[i] * d[i];
        render::TraceHit hit;
        hits += tracer.intersect(render::TraceRay{ro, rd, 0, std::numeric_limits<double>::infinity()}, hit, scratch);
    }
    return hits;
}

}  // namespace

TEST_CASE("tile culling never drops a ray that hits", "[render][cull]") {
    const csg::Scene s = make_scene(op(Op::Union, {leaf(sphere(1, translate(0.5, 0, 0))),
                                                   leaf(box({-2, -0.5, -0.5}, {-1, 0.5, 0.3}))}));
    const render::CsgTracer tracer(s, false);
    render::TraceScratch scratch;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
    int culled = 0, kept = 0;
    for (int q = 0; q < 4000; ++q) {
        const bool pinhole = q % 2 == 0;
        const glm::dvec3 eye(6 * u(rng), -8, 6 * u(rng));
        const glm::dvec3 aim = glm::normalize(glm::dvec3(2 * u(rng), 0, 2 * u(rng)) - eye);
        const glm::dvec3 right = glm::normalize(glm::cross(aim, {0, 0, 1})), up = glm::cross(right, aim);
        const double size = 0.02 + 0.3 * w(rng);  // tile size on the image plane (or in world, orthographic)
        const double cx = u(rng), cy = u(rng);
        glm::dvec3 o[4], d[4];
        const double sx[4] = {0, 1, 1, 0}, sy[4] = {0, 0, 1, 1};
        for (int i = 0; i < 4; ++i) {
            const double px = cx + size * sx[i], py = cy + size * sy[i];
            if (pinhole) {
                o[i] = eye;
                d[i] = glm::normalize(aim + 0.4 * px * right + 0.4 * py * up);
            } else {
                o[i] = eye + 3 * px * right + 3 * py * up;
                d[i] = aim;
            }
        }
        if (!tracer.misses_all(o, d)) {
            ++kept;
            continue;
        }
        ++culled;
        INFO("quad " << q << (pinhole ? " pinhole" : " orthographic"));
        CHECK(hits_in_quad(tracer, scratch, o, d, 40, rng) == 0);
    }
    INFO(culled << " culled, " << kept << " kept");
    CHECK(culled > 500);
    CHECK(kept > 500);
}

// A quad with two corner rays the same (a far origin or a vanishing field
// of view rounds them together) has a degenerate side plane; the plane
// before it takes its side from a corner lying in it, so its sign is
// round-off. Here it comes out facing away from the quad: a sphere inside
// the quad's rays must still be traced (culling it would drop real hits).
TEST_CASE("tile culling keeps a quad with two corner rays the same", "[render][cull]") {
    const glm::dvec3 eye(0, 0, 0), c(0, 5, -0.03);
    const glm::dvec3 o[4] = {eye, eye, eye, eye};
    const glm::dvec3 d[4] = {{-0.12, 1, -0.12}, {0.12, 1, -0.12}, {0.12, 1, -0.12}, {0, 1, 0.12}};
    for (const bool ball : {false, true}) {
        const csg::Scene s =
            ball ? make_scene(leaf(sphere(0.25, translate(c.x, c.y, c.z))))
                 : make_scene(op(Op::Union, {leaf(sphere(0.25, translate(c.x, c.y, c.z))),
                                             leaf(box({-0.02, 4.9, -0.05}, {0.02, 5.1, -0.01}))}));
        const render::CsgTracer tracer(s, false);
        render::TraceScratch scratch;
        std::mt19937_64 rng(3);
        INFO((ball ? "one ball" : "a ball and a box"));
        REQUIRE(hits_in_quad(tracer, scratch, o, d, 40, rng) > 0);
        CHECK_FALSE(tracer.misses_all(o, d)); CHECK_FALSE(render::tile_misses_box(csg::Aabb{{-0.25, 4.75, -0.28}, {0.25, 5.25, 0.22}}, o, d));
        CHECK_FALSE(render::tile_misses_box(csg::Aabb{{-0.1, 4.9, -0.1}, {0.1, 5.1, 0.05}}, o, d));
    }
}

namespace {

// Solids whose units have balls (unit_balls.hpp), moved by `at` and scaled
// by `s`: a fishbowl (a ball minus a smaller one and a cone), a lens (two
// balls intersected), and, when `crowd`, those two beside a box (no ball)
// and a sphere minus a box, as units of one union.
csg::Scene ball_units(double s, glm::dvec3 at, bool crowd) {
    const glm::dmat4 m = translate(at.x, at.y, at.z) * scale(s, s, s);
    auto fishbowl = [&](glm::dvec3 c) {
        const glm::dmat4 p = m * translate(c.x, c.y, c.z);
        return op(Op::Difference,
                  {leaf(sphere(1, p)), leaf(sphere(0.9, p)),
                   leaf(make_leaf(csg::PrimKind::Cylinder, {0, 1.2, 0.6, 0},
                                  p * translate(0, 0, 1.2) * scale(1, 1, -1)))});
    };
    auto lens = [&](glm::dvec3 c) {
        return op(Op::Intersection, {leaf(sphere(1, m * translate(c.x, c.y, c.z - 0.6))),
                                     leaf(sphere(1, m * translate(c.x, c.y, c.z + 0.6)))});
    };
    if (!crowd) return make_scene(fishbowl({0, 0, 0}));
    return make_scene(op(Op::Union, {fishbowl({1.4, 0, 0}), lens({-1.4, 0, 0.3}),
                                     leaf(box({-0.3, -0.3, 1.6}, {0.3, 0.3, 1.9}, m)),
                                     op(Op::Difference, {leaf(sphere(0.5, m * translate(0, 0.5, -1.5))),
                                                         leaf(box({-1, -1, -1.5}, {1, 1, -1.2}, m))})}));
}

}  // namespace

// Scenes of few units are culled unit by unit, each by its ball: a quad is
// culled only when every ray of it misses (intersect, sampled), also when
// the quad is tiny and lies just outside a ball's outline (1e-7 to 1e-1 of
// its radius), at 1e-3, 1e4 and 1e6 moved off the origin; and the balls
// cull quads the scene's box keeps (else they would save nothing).
TEST_CASE("tile culling by unit balls never drops a ray that hits", "[render][cull]") {
    struct Case {
        double s;
        glm::dvec3 at;
        bool crowd;
    };
    const Case cases[] = {{1, {0, 0, 0}, false}, {1, {0, 0, 0}, true}, {1e-3, {5e-3, -3e-3, 2e-3}, true},
                          {1e4, {2e4, 0, -1e4}, true}, {1e6, {3e6, 1e6, 0}, false}};
    for (const Case& c : cases) {
        const csg::Scene s = ball_units(c.s, c.at, c.crowd);
        const render::CsgTracer tracer(s, false);
        render::TraceScratch scratch;
        csg::Aabb all;
        for (const csg::Node& n : s.nodes) all.extend(n.bounds);
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
        int culled = 0, kept = 0, beyond_box = 0;
        for (int q = 0; q < 3000; ++q) {
            const bool pinhole = q % 2 == 0;
            const glm::dvec3 eye = c.at + c.s * glm::dvec3(6 * u(rng), -8, 6 * u(rng));
            // Half the quads aim round the whole scene, half just outside
            // (or inside) the outline of a ball of one fishbowl unit.
            glm::dvec3 target = c.at + c.s * glm::dvec3(2 * u(rng), 0, 2 * u(rng));
            double size = 0.02 + 0.3 * w(rng);
            const bool graze = q % 4 >= 2;
            if (graze) {
                const glm::dvec3 centre = c.at + c.s * glm::dvec3(c.crowd ? 1.4 : 0, 0, 0);
                const glm::dvec3 view = glm::normalize(centre - eye);
                const glm::dvec3 side = glm::normalize(glm::cross(view, glm::dvec3(u(rng), u(rng), u(rng))));
                const double gap = (q % 8 < 6 ? 1 : -1) * std::pow(10.0, -7 + 6 * w(rng));
                // The tangent ray's direction leans out by the gap.
                const double dist = glm::length(centre - eye), r = c.s * (1 + gap);
                target = eye + dist * (std::sqrt(std::max(0.0, 1 - r * r / (dist * dist))) * view + r / dist * side);
                size = std::pow(10.0, -6 + 5 * w(rng));
            }
            const glm::dvec3 aim = glm::normalize(target - eye);
            const glm::dvec3 right = glm::normalize(glm::cross(aim, {0, 0, 1})), up = glm::cross(right, aim);
            glm::dvec3 o[4], d[4];
            const double sx[4] = {0, 1, 1, 0}, sy[4] = {0, 0, 1, 1};
            for (int i = 0; i < 4; ++i) {
                const double px = size * (sx[i] - 0.5), py = size * (sy[i] - 0.5);
                if (pinhole) {
                    o[i] = eye;
                    d[i] = glm::normalize(aim + 0.4 * px * right + 0.4 * py * up);
                } else {
                    o[i] = eye + c.s * (3 * px * right + 3 * py * up);
                    d[i] = aim;
                }
            }
            if (!tracer.misses_all(o, d)) {
                ++kept;
                continue;
            }
            ++culled;
            if (!render::tile_misses_box(all, o, d)) ++beyond_box;
            INFO("scale " << c.s << " quad " << q << (pinhole ? " pinhole" : " orthographic"));
            CHECK(hits_in_quad(tracer, scratch, o, d, 24, rng) == 0);
        }
        INFO("scale " << c.s << ": " << culled << " culled (" << beyond_box << " beyond the box), " << kept << " kept");
        CHECK(culled > 300);
        CHECK(beyond_box > 100);
        CHECK(kept > 300);
    }
}

// Crowds of more than 128 units seen by the scene's pinhole camera are
// culled unit by unit from the camera's position (CsgTracer::near_units,
// Impl::cull_from): a tile lists the units its rays may meet, and each of
// its four sub-quads (an image block) asks only those. A quad whose list
// is empty must have every sampled ray miss (intersect), also when it is
// tiny and lies just inside or outside a cell's outline (1e-8 to 1e-1 of
// its radius), at 1e-3, 1e4 and 1e6 moved off the origin; and quads must be
// culled often, also where the crowd's box keeps them. (With the radii
// found from the camera 1e-6 too small it fails 8 checks.)
TEST_CASE("crowds are culled unit by unit from the camera", "[render][cull]") {
    struct Case {
        double s;
        glm::dvec3 at;
    };
    const Case cases[] = {{1, {0, 0, 0}}, {1e-3, {5e-3, -3e-3, 2e-3}}, {1e4, {2e4, 0, -1e4}}, {1e6, {3e6, 1e6, 0}}};
    for (const Case& c : cases) {
        // 300 hollow cells (a sphere minus a smaller one raised through its
        // top, as bench/scenes.py's cells) on a 15 × 20 grid, apart: so
        // that quads round one cell's outline are culled.
        std::vector<Tree> cells;
        std::vector<glm::dvec3> centres;
        for (int k = 0; k < 300; ++k) {
            const glm::dvec3 p = c.at + c.s * glm::dvec3(0.6 * (k % 15 - 7), 0.6 * (k / 15 - 9.5), 0.1 * std::sin(k));
            const glm::dmat4 m = translate(p.x, p.y, p.z) * scale(c.s, c.s, c.s);
            centres.push_back(p);
            cells.push_back(op(Op::Difference, {leaf(sphere(0.2, m)), leaf(sphere(0.17, m * translate(0, 0, 0.05)))}));
        }
        csg::Scene s = make_scene(op(Op::Union, cells));
        s.camera.position = c.at + c.s * glm::dvec3(0.3, -1, 12);  // from above: the cells' outlines apart
        const glm::dvec3 eye = s.camera.position;
        const render::CsgTracer tracer(s, false);
        REQUIRE(tracer.cull_unit_count() == 300);
        render::TraceScratch scratch;
        csg::Aabb all;
        for (const csg::Node& n : s.nodes) all.extend(n.bounds);
        std::mt19937_64 rng(13);
        std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
        std::vector<std::uint32_t> tile(300), block(300);
        int culled = 0, kept = 0, beyond_box = 0, listed = 0;
        for (int q = 0; q < 1500; ++q) {
            glm::dvec3 target = c.at + c.s * glm::dvec3(5 * u(rng), 6.5 * u(rng), 0.3 * u(rng));
            double size = 0.01 + 0.1 * w(rng);
            if (q % 4 >= 2) {
                // Just outside (or inside) the outline of one cell's ball.
                const glm::dvec3 centre = centres[std::size_t(300 * w(rng)) % 300];
                const glm::dvec3 view = glm::normalize(centre - eye);
                const glm::dvec3 side = glm::normalize(glm::cross(view, glm::dvec3(u(rng), u(rng), u(rng))));
                const double gap = (q % 8 < 5 ? 1 : -1) * std::pow(10.0, -8 + 7 * w(rng));
                const double dist = glm::length(centre - eye), r = 0.2 * c.s * (1 + gap);
                target = eye + dist * (std::sqrt(std::max(0.0, 1 - r * r / (dist * dist))) * view + r / dist * side);
                size = std::pow(10.0, -9 + 8 * w(rng));
            }
            const glm::dvec3 aim = glm::normalize(target - eye);
            const glm::dvec3 right = glm::normalize(glm::cross(aim, {0, 0, 1})), up = glm::cross(right, aim);
            // The tile's corner directions, then its four sub-quads'.
            const auto dir = [&](double x, double y) {
                return glm::normalize(aim + 0.4 * size * (x - 0.5) * right + 0.4 * size * (y - 0.5) * up);
            };
            glm::dvec3 o[4] = {eye, eye, eye, eye};
            glm::dvec3 d[4] = {dir(0, 0), dir(1, 0), dir(1, 1), dir(0, 1)};
            const int ntile = tracer.near_units(o, d, nullptr, 0, tile.data());
            REQUIRE(ntile >= 0);
            CHECK((ntile == 0) == tracer.misses_all(o, d));
            listed += ntile > 0 && ntile < 300;
            for (int b = 0; b < 5; ++b) {
                int n = ntile;
                if (b > 0) {
                    const double x0 = 0.5 * ((b - 1) % 2), y0 = 0.5 * ((b - 1) / 2);
                    d[0] = dir(x0, y0), d[1] = dir(x0 + 0.5, y0), d[2] = dir(x0 + 0.5, y0 + 0.5), d[3] = dir(x0, y0 + 0.5);
                    n = ntile == 0 ? 0 : tracer.near_units(o, d, tile.data(), ntile, block.data());
                }
                if (n > 0) {
                    ++kept;
                    continue;
                }
                ++culled;
                if (!render::tile_misses_box(all, o, d)) ++beyond_box;
                INFO("scale " << c.s << " quad " << q << " part " << b);
                CHECK(hits_in_quad(tracer, scratch, o, d, 24, rng) == 0);
            }
        }
        INFO("scale " << c.s << ": " << culled << " culled (" << beyond_box << " beyond the box), " << kept
                      << " kept, " << listed << " tiles listing some units");
        CHECK(culled > 1000);
        CHECK(beyond_box > 500);
        CHECK(kept > 1000);
        CHECK(listed > 500);
    }
}

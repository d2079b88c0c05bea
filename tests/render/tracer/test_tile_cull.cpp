// CsgTracer::misses_all culls whole image tiles; it must never cull a tile
// one of whose rays hits the solid. Random quads of rays around a few
// solids, pinhole and orthographic: whenever a quad is culled, rays mixed
// from its corners (convex combinations, as a tile's pixels are) all miss
// by intersect(); and culling must happen often, or it saves nothing.
#include <catch2/catch.hpp>

#include <limits>
#include <random>

#include "render/tracer/tracer.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

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
        for (int k = 0; k < 40; ++k) {
            // A point of the quad: bilinear weights, as pixels inside a tile.
            const double a = k < 4 ? sx[k] : w(rng), b = k < 4 ? sy[k] : w(rng);
            const double wt[4] = {(1 - a) * (1 - b), a * (1 - b), a * b, (1 - a) * b};
            glm::dvec3 ro(0.0), rd(0.0);
            for (int i = 0; i < 4; ++i) ro += wt[i] * o[i], rd += wt[i] * d[i];
            render::TraceHit hit;
            INFO("quad " << q << (pinhole ? " pinhole" : " orthographic") << " sample " << k);
            CHECK_FALSE(tracer.intersect(render::TraceRay{ro, rd, 0, std::numeric_limits<double>::infinity()}, hit,
                                         scratch));
        }
    }
    INFO(culled << " culled, " << kept << " kept");
    CHECK(culled > 500);
    CHECK(kept > 500);
}

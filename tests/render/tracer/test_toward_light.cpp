// Shadow rays of a bare-sphere crowd toward a point light, as the shader
// sends them from a sphere it hit (render/tracer/toward_light.hpp): the
// units listed between that sphere and the light answer them, and the
// thread's last blocker is tried first (bare_spheres.cpp). Checked against
// the first entry along the same ray (the camera query, its answer checked
// by point membership): lattices and random overlapping crowds, through
// the cones' own grid (512, 300 units) and the crowd's grid (4,913 units),
// lights far above, close beside and inside the crowd, two lights at once,
// at unit size, 1e4 and 1e6 from the origin. Hits come from rays aimed at
// a few spheres from all sides, so each sphere's list is asked many times
// on the primed thread, and half of them near the terminator, whose shadow
// rays graze the neighbours at the edge of what the lists must hold.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "render/tracer/tracer.hpp"
#include "tests/render/grazing_rays.hpp"
#include "tests/render/random_csg.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct LightCase {
    std::uint64_t seed;
    glm::dvec3 at;
    double size;
    int n;
    bool lattice;
    std::vector<glm::dvec3> lights;  // in crowd sizes from `at`
    int rays;
    bool from_first_light = false;  // the hits' rays start near the first light, not outside the crowd
};

struct Counts {
    int lit = 0, shadowed = 0;
    std::uint64_t listed = 0;
};

Counts check(const LightCase& k) {
    RandomCsg g(k.seed);
    std::vector<Ball> balls;
    Tree tree = op(Op::Union, {});
    if (k.lattice) {
        const int m = int(std::lround(std::cbrt(double(k.n))));
        const double p = 2 * k.size / m;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j)
                for (int l = 0; l < m; ++l)
                    balls.push_back({k.at + p * glm::dvec3(i + 0.5 - 0.5 * m, j + 0.5 - 0.5 * m, l + 0.5 - 0.5 * m), 0.35 * p});
    } else {
        for (int i = 0; i < k.n; ++i)
            balls.push_back({k.at + k.size * glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)), k.size * g.uni(0.1, 0.25)});
    }
    for (const Ball& b : balls) tree.kids.push_back(leaf(sphere(b.r, translate(b.c.x, b.c.y, b.c.z))));
    csg::Scene s = make_scene(tree);
    s.camera.position = k.at + k.size * glm::dvec3(3, -8, 4);
    s.camera.look_at = k.at;
    s.lights.clear();
    for (const glm::dvec3& l : k.lights) s.lights.push_back(csg::Light{false, k.at + k.size * l, {0, 0, -1}, {1, 1, 1}, 1});
    const render::CsgTracer tracer(s, false);
    render::TraceScratch kept, fresh;
    Counts c;
    // A handful of target spheres, each hit many times.
    std::vector<std::size_t> targets;
    for (int i = 0; i < 12; ++i) targets.push_back(std::size_t(g.pick(int(balls.size()))));
    for (int i = 0; i < k.rays; ++i) {
        // (From inside the crowd, any sphere: those near the light are seen.)
        const Ball& b = k.from_first_light ? balls[std::size_t(g.pick(int(balls.size())))]
                                           : balls[targets[std::size_t(i) % targets.size()]];
        const glm::dvec3 u = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
        glm::dvec3 from = k.from_first_light ? s.lights[0].position + 0.01 * k.size * u : k.at + 3 * k.size * u;
        glm::dvec3 d = k.size * aim(g, from, b, 1e-4, false);
        if (i % 2 == 1) {
            // A point near the sphere's terminator (the light grazing it,
            // a little on its lit side), hit from just above it: its
            // shadow ray runs along the rim of the capsule round the
            // sphere's listed units, past the neighbours at its edge.
            // Every other one on the side of the neighbour nearest the
            // sphere's axis to the light: that ray passes it at the
            // distance the capsule's edge has from its centre, less r.
            const glm::dvec3 a = glm::normalize(s.lights[std::size_t(i / 2) % s.lights.size()].position - b.c);
            glm::dvec3 side = u;
            if (i % 4 == 3) {
                double best = kInf;
                for (const Ball& o : balls) {
                    const glm::dvec3 w = o.c - b.c;
                    const glm::dvec3 q = w - glm::dot(w, a) * a;
                    if (glm::dot(w, a) > 0 && glm::dot(q, q) > 1e-6 * b.r * b.r && glm::length(q) - o.r < best) {
                        best = glm::length(q) - o.r;
                        side = q;
                    }
                }
            }
            const glm::dvec3 e = glm::normalize(side - glm::dot(side, a) * a);
            const double phi = g.uni(-0.02, 0.25);
            const glm::dvec3 nq = std::cos(phi) * e + std::sin(phi) * a;
            from = b.c + 1.02 * b.r * nq;
            d = -nq;
            if (csg_contains(s, from)) continue;
        }
        render::TraceHit hit;
        if (!tracer.intersect(render::TraceRay{from, d, 0, kInf}, hit, fresh)) continue;
        const glm::dvec3 p = from + hit.t * d;
        glm::dvec3 nrm = tracer.normal(hit, p);
        if (glm::dot(nrm, d) > 0) continue;  // (grazing round-off: the shader sends no departing ray)
        const glm::dvec3 o = p + tracer.surface_offset(hit, p) * nrm;
        const render::Departure dep = tracer.departure(hit, nrm);
        for (const csg::Light& light : s.lights) {
            const double dist = glm::length(light.position - o);
            const glm::dvec3 l = (light.position - o) / dist;
            if (!(glm::dot(nrm, l) > 0)) continue;
            render::TraceHit e;
            const double te = tracer.intersect(render::TraceRay{o, l, 0, kInf}, e, fresh) ? e.t : kInf;
            INFO("case " << k.seed << " ray " << i << " entry " << te << " light at " << dist);
            CHECK(is_first_entry(s, o, l, te, dist, 1e-7 * k.size));
            CHECK(tracer.occluded(render::TraceRay{o, l, 0, dist}, kept, &dep) == (te < dist));
            (te < dist ? c.shadowed : c.lit)++;
        }
    }
    c.listed = kept.counters.listed_shadows;
    return c;
}

const glm::dvec3 kFar = 1e6 * glm::normalize(glm::dvec3(0.4, -1, 0.3));

}  // namespace

TEST_CASE("toward the light: departing shadow rays of bare-sphere crowds answered by the units listed between "
          "their sphere and the light",
          "[render][oracle]") {
    // (A lattice's light in the gap between eight of its spheres: pitch 0.25
    // at n = 512, so the corner (0.125, 0.125, 0.125) of the middle cell.)
    const std::vector<LightCase> cases = {
        {31, glm::dvec3(0.0), 1, 512, true, {{-5, -7, 10}}, 400},
        {32, glm::dvec3(0.0), 1, 512, true, {{0.4, -2.5, 1.2}, {-1.5, 0.3, -0.2}}, 300},
        {33, glm::dvec3(0.0), 1, 512, true, {{0.125, 0.125, 0.125}, {-5, -7, 10}}, 300, true},
        {34, glm::dvec3(0.0), 1, 300, false, {{-5, -7, 10}, {0.2, -1.6, 0.4}}, 300},
        {35, glm::dvec3(0.0), 1e4, 512, true, {{2, -3, 1.5}}, 200},
        {36, kFar, 1, 512, true, {{-5, -7, 10}}, 200},
        {37, kFar, 1, 300, false, {{-5, -7, 10}, {1.2, 1.4, -1.7}}, 200},
        {38, glm::dvec3(0.0), 1, 4913, true, {{-5, -7, 10}}, 40},
    };
    // Small lattices under lights from many directions: some neighbour's
    // ball lies at the capsule's very edge for some of them.
    RandomCsg g(39);
    std::vector<LightCase> all = cases;
    for (int i = 0; i < 30; ++i) {
        const glm::dvec3 l = 6.0 * glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
        all.push_back({std::uint64_t(100 + i), glm::dvec3(0.0), 1, 125, true, {l}, 120});
    }
    for (const LightCase& k : all) {
        const Counts c = check(k);
        INFO("case " << k.seed << ": lit " << c.lit << ", shadowed " << c.shadowed << ", listed " << c.listed);
        CHECK(c.lit > 0);
        CHECK(c.shadowed > 0);
        CHECK(c.listed > 0);
    }
}

TEST_CASE("the last blocker first: a shadow ray that passes just outside it, or ends or starts just short of it, "
          "is not blocked by it",
          "[render][oracle]") {
    // Each trial blocks a ray by sphere X (so X is the thread's last
    // blocker), then asks rays that pass X at 1.0001 to 1.02 of its radius,
    // and rays leaving its surface from 1e-5 to 5e-4 of its radius outside:
    // X is tried first and must not answer them.
    for (const int n : {512, 4913}) {
        RandomCsg g(40 + std::uint64_t(n));
        Tree tree = op(Op::Union, {});
        std::vector<Ball> balls;
        const int m = int(std::lround(std::cbrt(double(n))));
        const double p = 2.0 / m;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j)
                for (int l = 0; l < m; ++l) {
                    balls.push_back({p * glm::dvec3(i + 0.5 - 0.5 * m, j + 0.5 - 0.5 * m, l + 0.5 - 0.5 * m), 0.35 * p});
                    tree.kids.push_back(leaf(sphere(balls.back().r, translate(balls.back().c.x, balls.back().c.y, balls.back().c.z))));
                }
        const csg::Scene s = make_scene(tree);
        const render::CsgTracer tracer(s, false);
        render::TraceScratch kept, fresh;
        int passed = 0, left = 0, blocked = 0;
        for (int trial = 0; trial < (n > 1000 ? 60 : 200); ++trial) {
            const Ball& x = balls[std::size_t(g.pick(int(balls.size())))];
            const auto unit = [&] { return glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3); };
            const auto agrees = [&](const glm::dvec3& o, const glm::dvec3& d, double tfar) {
                if (csg_contains(s, o)) return -1;
                render::TraceHit e;
                const double te = tracer.intersect(render::TraceRay{o, d, 0, kInf}, e, fresh) ? e.t : kInf;
                INFO("trial " << trial << " entry " << te << " segment " << tfar);
                CHECK(is_first_entry(s, o, d, te, tfar, 1e-9));
                CHECK(tracer.occluded(render::TraceRay{o, d, 0, tfar}, kept) == (te < tfar));
                return te < tfar ? 1 : 0;
            };
            // A: through X's centre from 0.2 pitch off its surface.
            const glm::dvec3 u = unit();
            const glm::dvec3 oa = x.c + (x.r + 0.2 * p * g.uni(0.2, 1)) * u;
            blocked += agrees(oa, -u, glm::length(x.c - oa)) == 1;
            // B: beside X, 1.0001 to 1.02 radii from its centre.
            const glm::dvec3 e = unit();
            const glm::dvec3 t = unit();
            const glm::dvec3 f = glm::normalize(t - glm::dot(t, e) * e);
            const double off = x.r * (1 + std::pow(10.0, g.uni(-4, std::log10(0.02))));
            // (Within 1.2 radii of X's centre, so clear of its neighbours.)
            passed += agrees(x.c + off * f - 0.6 * x.r * e, e, 1.2 * x.r) == 0;
            // Again through X, then C: leaving X from just outside its surface.
            agrees(oa, -u, glm::length(x.c - oa));
            const glm::dvec3 v = unit();
            left += agrees(x.c + x.r * (1 + std::pow(10.0, g.uni(-5, std::log10(5e-4)))) * v, v, 0.05 * p) == 0;
        }
        INFO("lattice " << n << ": blocked " << blocked << ", passed " << passed << ", left " << left);
        CHECK(blocked > 20);
        CHECK(passed > 20);
        CHECK(left > 20);
    }
}

// Crowds of bare spheres (render/tracer/bare_spheres.hpp): every unit a
// sphere leaf, so the units keep their balls, and camera rays (starting at
// the camera) and shadow rays (ending at the light) of the ray cones take
// the bare loop instead of the general query. Checked against point
// membership along the ray (no ray code): lattices like bench/scenes.py's
// spheres(n) and random overlapping crowds with coincident pairs (ties go
// by unit index), one level (60 units) and two (343, 320), at unit size,
// tiny (1e-4), huge (1e4) and 1e6 from the origin; rays aimed within
// ±0.01 % of the spheres or tangent to them; shadow rays from points near
// the spheres and, as the shader makes them, from lit points with their
// Departure (the unit left is skipped). The float path keeps no leaf balls
// and takes the general query: checked the same way. Crowds of more than
// 4,096 units (17³ lattices, 5,000 random spheres) walk a grid of the
// balls instead of cones (sphere_grid.hpp), at the same scales.
#include <catch2/catch.hpp>

#include <algorithm>
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

struct Crowd {
    csg::Scene scene;
    std::vector<Ball> balls;  // per unit, in the union's order
    std::vector<std::pair<std::uint32_t, std::uint32_t>> twins;  // coincident units (i < j)
};

// A lattice of k³ spheres (pitch 2·size/k... radius 0.35 pitch, as
// spheres(n)) or n random overlapping spheres of radii within 2× (a few of
// them doubled: the same sphere twice), around `at`.
Crowd bare_crowd(RandomCsg& g, const glm::dvec3& at, double size, int n, bool lattice, double away = 1) {
    Crowd c;
    Tree tree = op(Op::Union, {});
    if (lattice) {
        const int k = int(std::lround(std::cbrt(double(n))));
        const double p = 2 * size / k;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j)
                for (int l = 0; l < k; ++l)
                    c.balls.push_back({at + p * glm::dvec3(i + 0.5 - 0.5 * k, j + 0.5 - 0.5 * k, l + 0.5 - 0.5 * k), 0.35 * p});
    } else {
        for (int i = 0; i < n; ++i) {
            if (i % 10 == 9) {
                c.twins.push_back({std::uint32_t(i - 1), std::uint32_t(i)});
                c.balls.push_back(c.balls.back());
                continue;
            }
            const glm::dvec3 p = size * glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1));
            c.balls.push_back({at + p, size * g.uni(0.15, 0.3)});
        }
    }
    for (const Ball& b : c.balls) {
        // Translations relative to `at` as the scene's own numbers: far from
        // the origin the centre is at + offset, rounded once.
        tree.kids.push_back(leaf(sphere(b.r, translate(b.c.x, b.c.y, b.c.z))));
    }
    c.scene = make_scene(tree);
    c.scene.camera.position = at + away * size * glm::dvec3(3, -8, 4);
    c.scene.camera.look_at = at;
    c.scene.lights[0].position = at + size * glm::dvec3(-5, -7, 10);
    return c;
}

struct Result {
    int hits = 0, shadows = 0, departures = 0, twin_hits = 0;
    std::uint64_t cones = 0, cells = 0;
};

Result check(std::uint64_t seed, const glm::dvec3& at, double size, int n, bool lattice, bool use_float, double h,
             int rays, double away = 1) {
    const double band = use_float ? 1e-2 : 1e-4;
    RandomCsg g(seed);
    const Crowd c = bare_crowd(g, at, size, n, lattice, away);
    const csg::Scene& s = c.scene;
    const glm::dvec3 cam = s.camera.position, light = s.lights[0].position;
    const render::CsgTracer tracer(s, use_float);
    render::TraceScratch kept;  // primed by every earlier ray, as a render thread
    Result res;
    for (int i = 0; i < rays; ++i) {
        const std::size_t k = std::size_t(g.pick(int(c.balls.size())));
        const Ball& b = c.balls[k];
        INFO("seed " << seed << " ray " << i << " unit " << k);
        // A camera ray: the same entry and the same work on a fresh thread
        // and on the primed one; the entry by point membership.
        const glm::dvec3 d = size * aim(g, cam, b, band, i % 2 == 1 && !use_float);
        const render::TraceRay ray{cam, d, 0, kInf};
        render::TraceScratch fresh;
        render::TraceHit hit;
        const bool found = camera_ray_agrees(s, tracer, ray, fresh, kept, 30, h, &hit);
        res.hits += found;
        if (found) {
            // Ties go by unit index: never the later of two coincident units.
            for (const auto& [u0, u1] : c.twins) {
                CHECK(hit.surface.leaf != u1);
                res.twin_hits += hit.surface.leaf == u0;
            }
            // The shader's shadow ray from the lit point, leaving its unit.
            const glm::dvec3 p = ray.o + hit.t * ray.d;
            const glm::dvec3 nrm = tracer.normal(hit, p);
            const glm::dvec3 o = p + tracer.surface_offset(hit, p) * nrm;
            const double dist = glm::length(light - o);
            const glm::dvec3 l = (light - o) / dist;
            if (glm::dot(nrm, l) > 0 && glm::dot(nrm, ray.d) < 0) {
                const render::Departure from = tracer.departure(hit, nrm);
                render::TraceHit e;
                const double te = tracer.intersect(render::TraceRay{o, l, 0, kInf}, e, fresh) ? e.t : kInf;
                INFO("departing shadow ray entry " << te << " light at " << dist);
                CHECK(is_first_entry(s, o, l, te, dist, h * size));
                CHECK(tracer.occluded(render::TraceRay{o, l, 0, dist}, kept, &from) == (te < dist));
                res.departures += te < dist;
            }
        }
        // A shadow ray from a point near ball b (outside the solid) to the
        // light: blocked exactly when the first entry comes before the light.
        ShadowRay sr;
        if (!shadow_ray(g, s, tracer, light, b, band, i % 2 == 0 && !use_float, size, 8, 20, h * size, fresh, sr))
            continue;
        CHECK(tracer.occluded(render::TraceRay{sr.o, sr.dir, 0, sr.dist}, kept) == (sr.te < sr.dist));
        res.shadows += sr.te < sr.dist;
    }
    res.cones = kept.cones.built;
    res.cells = kept.counters.grid_cells;
    return res;
}

struct Case {
    std::uint64_t seed;
    glm::dvec3 at;
    double size;
    int n;
    bool lattice, use_float;
    double h;
    int rays;
    double away = 1;  // the camera's distance, in units of its usual one
};

const glm::dvec3 kFar = 1e6 * glm::normalize(glm::dvec3(0.4, -1, 0.3));

// Every case's rays against point membership. The double path's rays went
// through cones (so through the bare loop), or for crowds past the cones'
// 4,096 units (`grid`) walked the balls' grid; the float path's take
// neither (no leaf balls).
void check_cases(const std::vector<Case>& cases, bool grid) {
    for (const Case& k : cases) {
        INFO("case " << k.seed);
        const Result r = check(k.seed, k.at, k.size, k.n, k.lattice, k.use_float, k.h, k.rays, k.away);
        CHECK(r.hits > k.rays / 3);
        CHECK(r.shadows > k.rays / 20);
        CHECK(r.departures > 0);
        if (!k.lattice) CHECK(r.twin_hits > 0);
        CHECK((r.cones > 0) == (!k.use_float && !grid));
        CHECK((r.cells > 0) == (!k.use_float && grid));
    }
}

}  // namespace

TEST_CASE("bare spheres: camera and shadow rays through crowds of sphere leaves keep every entry and shadow",
          "[render][oracle]") {
    check_cases({{1, glm::dvec3(0.0), 1, 60, false, false, 1e-7, 300},
                 {2, glm::dvec3(0.0), 1, 343, true, false, 1e-7, 200},
                 {3, glm::dvec3(0.0), 1, 320, false, false, 1e-7, 200},
                 {4, glm::dvec3(0.0), 1e-4, 320, false, false, 1e-7, 120},
                 {5, glm::dvec3(0.0), 1e4, 343, true, false, 1e-7, 120},
                 {6, kFar, 1, 320, false, false, 1e-6, 120},
                 {7, kFar, 1, 64, true, false, 1e-6, 120},
                 {8, glm::dvec3(0.0), 1, 320, false, true, 1e-4, 120}},
                false);
}

TEST_CASE("bare spheres: past the cones' 4,096 units, rays walk the balls' grid and keep every entry and shadow",
          "[render][oracle]") {
    check_cases({{11, glm::dvec3(0.0), 1, 4913, true, false, 1e-7, 80},
                 {12, glm::dvec3(0.0), 1, 5000, false, false, 1e-7, 80},
                 {13, glm::dvec3(0.0), 1e-4, 4913, true, false, 1e-7, 40},
                 {14, glm::dvec3(0.0), 1e-4, 5000, false, false, 1e-7, 80},
                 {15, glm::dvec3(0.0), 1e4, 4913, true, false, 1e-7, 40},
                 {16, glm::dvec3(0.0), 1e4, 5000, false, false, 1e-7, 80},
                 {17, kFar, 1, 4913, true, false, 1e-6, 40},
                 {18, kFar, 1, 5000, false, false, 1e-6, 80},
                 {19, glm::dvec3(0.0), 1, 5000, false, true, 1e-4, 30},
                 // A camera 3,000 crowd sizes away: its rays' round-off exceeds
                 // the grid's margin (SphereGrid::fits), so they take the general
                 // path, whose top BVH no ray needed before (built on this first
                 // query, Accel::ready); the light's rays still walk the grid.
                 {20, glm::dvec3(0.0), 1, 5000, false, false, 1e-7, 24, 3000},
                 {21, glm::dvec3(0.0), 1, 4913, true, false, 1e-7, 24, 3000}},
                true);
}

TEST_CASE("bare spheres: the grid's walk in every octant, along the axes, with denormal components and from cell planes",
          "[render][oracle]") {
    // An 18³ lattice (5,832 units: the grid) centred on the origin, so the
    // planes x, y or z = 0 are cell planes. The rays of the other cases all
    // run towards -x; here each axis is walked up and down, exactly along
    // it (the other steps never taken), with a component so small its
    // reciprocal overflows (walked as parallel), and from a start on a cell
    // plane. Entries by point membership, shadows to a light on the +x side.
    RandomCsg g(31);
    Crowd c = bare_crowd(g, glm::dvec3(0.0), 1, 5832, true);
    c.scene.lights[0].position = glm::dvec3(6, 5, -4);
    const csg::Scene& s = c.scene;
    const render::CsgTracer tracer(s, false);
    render::TraceScratch kept;
    std::vector<std::pair<glm::dvec3, glm::dvec3>> rays;  // (origin, direction)
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 sign((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
        const glm::dvec3 d = sign * glm::dvec3(g.uni(0.3, 1), g.uni(0.3, 1), g.uni(0.3, 1));
        rays.push_back({-2.5 * sign + 0.2 * glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)), d});
    }
    for (int axis = 0; axis < 3; ++axis)
        for (const double dir : {1.0, -1.0}) {
            glm::dvec3 o(g.uni(-0.9, 0.9), g.uni(-0.9, 0.9), g.uni(-0.9, 0.9)), d(0.0);
            o[axis] = -3 * dir;
            d[axis] = dir;
            rays.push_back({o, d});
            d[(axis + 1) % 3] = 1e-310 * dir;  // 1/d overflows
            rays.push_back({o, d});
            o[(axis + 1) % 3] = 0;  // and starts on that axis's middle cell plane (0 * inf)
            rays.push_back({o, d});
        }
    for (int axis = 0; axis < 3; ++axis)
        for (int k = 0; k < 2; ++k) {
            glm::dvec3 o(g.uni(-0.9, 0.9), g.uni(-0.9, 0.9), g.uni(-0.9, 0.9));
            o[axis] = 0;  // on a cell plane, between two lattice layers
            rays.push_back({o, glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)))});
        }
    const glm::dvec3 light = s.lights[0].position;
    int hits = 0, checked = 0;
    for (const auto& [o, d] : rays) {
        INFO("ray from " << o.x << ", " << o.y << ", " << o.z << " along " << d.x << ", " << d.y << ", " << d.z);
        if (csg_contains(s, o)) continue;
        ++checked;
        render::TraceHit hit;
        const double t = tracer.intersect(render::TraceRay{o, d, 0, kInf}, hit, kept) ? hit.t : kInf;
        hits += t < kInf;
        CHECK(is_first_entry(s, o, d, t, 8 / glm::length(d), 1e-7));
        const double dist = glm::length(light - o);
        const glm::dvec3 l = (light - o) / dist;
        render::TraceHit e;
        const double te = tracer.intersect(render::TraceRay{o, l, 0, kInf}, e, kept) ? e.t : kInf;
        CHECK(is_first_entry(s, o, l, te, dist, 1e-7));
        CHECK(tracer.occluded(render::TraceRay{o, l, 0, dist}, kept) == (te < dist));
    }
    CHECK(checked >= 20);
    CHECK(hits >= 10);
    CHECK(kept.counters.grid_cells > 0);
}

TEST_CASE("bare spheres: a thread's kept cones serve three lights and the camera in turn, as a fresh thread's",
          "[render][oracle]") {
    // A two-level crowd (343 units) and lights on both sides: apexes 0-3
    // share the cones' slots (a and a + 2) and each remembers its last cell.
    // Shadow rays to each light in turn and camera rays between them, on one
    // kept scratch, against a fresh one and point membership.
    RandomCsg g(37);
    Crowd c = bare_crowd(g, glm::dvec3(0.0), 1, 343, true);
    c.scene.lights.push_back(c.scene.lights[0]);
    c.scene.lights.push_back(c.scene.lights[0]);
    c.scene.lights[1].position = glm::dvec3(6, 5, -4);
    c.scene.lights[2].position = glm::dvec3(-4, 7, 5);
    const csg::Scene& s = c.scene;
    const render::CsgTracer tracer(s, false);
    render::TraceScratch kept;
    int shadows = 0;
    for (int i = 0; i < 90; ++i) {
        const Ball& b = c.balls[std::size_t(g.pick(int(c.balls.size())))];
        const glm::dvec3 light = s.lights[std::size_t(i % 3)].position;
        INFO("ray " << i << " light " << i % 3);
        ShadowRay sr;
        render::TraceScratch fresh;
        if (shadow_ray(g, s, tracer, light, b, 1e-4, i % 2 == 0, 1, 8, 20, 1e-7, fresh, sr)) {
            const bool blocked = tracer.occluded(render::TraceRay{sr.o, sr.dir, 0, sr.dist}, kept);
            CHECK(blocked == (sr.te < sr.dist));
            shadows += blocked;
        }
        const render::TraceRay ray{s.camera.position, aim(g, s.camera.position, b, 1e-4, i % 2 == 1), 0, kInf};
        render::TraceScratch unused;  // (fresh served the shadow ray's oracle entry)
        camera_ray_agrees(s, tracer, ray, unused, kept, 30, 1e-7);
    }
    CHECK(shadows > 5);
    CHECK(kept.cones.built > 0);
}

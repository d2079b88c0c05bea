// Ray cones (render/tracer/ray_cones.hpp): camera rays (starting exactly at
// the scene's camera) and shadow rays ending at a point light test only the
// units whose grown balls meet a cone around them, built per thread by the
// first ray of a direction and reused by the rays within its half-angle.
// Checked against point membership along the ray (no ray code): rays aimed
// within ±0.01 % of the units' spheres (float: 1 %) and rays tangent to them
// (double only), each right
// after a ray that built a cone whose edge it nearly lies on (the grazed
// ball then lies at the cone's edge too), at unit size, tiny, huge and far
// from the origin, in double and float. And the cone never changes the
// work: a ray traced after another's cone counts the same primitive tests
// as on a fresh thread.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
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

// `n` overlapping units of `size` around `at` (within spread·size of it),
// every one inside a sphere
// (its ball; the cones serve crowds whose every unit has one): cells (a
// sphere minus 1-2 smaller spheres, sometimes a box too), sphere ∩ box,
// lenses. Similarities only, so `balls` (the spheres to aim at) are exact.
struct Crowd {
    Tree tree = op(Op::Union, {});
    std::vector<Ball> units, balls;
};

Crowd crowd(RandomCsg& g, const glm::dvec3& at, double size, int n = 60, const glm::dvec3& spread = glm::dvec3(1)) {
    Crowd c;
    for (int k = 0; k < n; ++k) {
        const double r = size * g.uni(0.3, 0.6);
        const glm::dvec3 p = at + size * (spread * glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)));
        const glm::dvec3 axis = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
        const glm::dmat4 m = translate(p.x, p.y, p.z) * rotate_deg(g.uni(0, 360), axis);
        c.units.push_back({p, r});
        c.balls.push_back({p, r});
        const int kind = g.pick(10);
        std::vector<Tree> kids{leaf(sphere(r, m))};
        if (kind < 7) {
            for (int h = 1 + g.pick(2); h > 0; --h) {
                const double ri = g.uni(0.5, 0.9) * r;
                const glm::dvec3 off = g.uni(-0.3, 0.3) * r * glm::dvec3(1, g.uni(-1, 1), g.uni(-1, 1));
                kids.push_back(leaf(sphere(ri, m * translate(off.x, off.y, off.z))));
                c.balls.push_back({glm::dvec3(m * glm::dvec4(off, 1)), ri});
            }
            if (g.pick(4) == 0) kids.push_back(leaf(box(glm::dvec3(-0.2 * r), glm::dvec3(0.2 * r), m)));
            c.tree.kids.push_back(op(Op::Difference, kids));
        } else if (kind < 9) {
            kids.push_back(leaf(box(glm::dvec3(-0.7 * r), glm::dvec3(0.7 * r), m)));
            c.tree.kids.push_back(op(Op::Intersection, kids));
        } else {
            kids.push_back(leaf(box(glm::dvec3(0.5 * r), glm::dvec3(2 * r), m)));  // a corner cut off
            c.tree.kids.push_back(op(Op::Difference, kids));
        }
    }
    return c;
}

// The crowd seen from at + camera, lit from at + light.
csg::Scene crowd_scene(const Crowd& c, const glm::dvec3& at, const glm::dvec3& camera, const glm::dvec3& light) {
    csg::Scene s = make_scene(c.tree);
    s.camera.position = at + camera;
    s.camera.look_at = at;
    s.lights[0].position = at + light;
    return s;
}

// The cones' half-angle around apex p as the tracer chooses it
// (ray_cones.cpp): half the middle unit ball's radius over the distance to
// the middle of the units' boxes (`part`: a quarter for two levels' narrow
// cones).
double cone_alpha(const csg::Scene& s, const Crowd& c, const glm::dvec3& p, double part = 0.5) {
    std::vector<double> r;
    for (const Ball& b : c.units) r.push_back(b.r);
    std::nth_element(r.begin(), r.begin() + long(r.size() / 2), r.end());
    csg::Aabb box;
    for (std::uint32_t k = 0; k < s.nodes[s.root].count; ++k) box.extend(s.nodes[s.children[s.nodes[s.root].first + k]].bounds);
    return std::clamp(part * r[r.size() / 2] / glm::length(0.5 * (box.lo + box.hi) - p), 1e-3, 0.25);
}

// d turned by `angle` away from the point c seen from p (in their plane).
glm::dvec3 turned_away(const glm::dvec3& d, const glm::dvec3& p, const glm::dvec3& c, double angle) {
    const glm::dvec3 w = c - p;
    const glm::dvec3 e = glm::normalize(w - glm::dot(w, d) / glm::dot(d, d) * d);
    return glm::length(d) * (std::cos(angle) * glm::normalize(d) - std::sin(angle) * e);
}

struct Result {
    int hits = 0, shadows = 0, in_primed = 0;
};

// Camera and shadow rays at the crowd of `size` around `at` (h: the
// oracle's step), each traced right after a ray whose cone it lies in,
// near its edge (`edge` of the half-angle off the axis).
Result check(std::uint64_t seed, const glm::dvec3& at, double size, double h, bool use_float, double edge) {
    const double band = use_float ? 1e-2 : 1e-4;
    RandomCsg g(seed);
    const Crowd c = crowd(g, at, size);
    const csg::Scene s = crowd_scene(c, at, size * glm::dvec3(1.5, -6, 2.5), size * glm::dvec3(-5, -8, 10));
    const glm::dvec3 cam = s.camera.position, light = s.lights[0].position;
    const render::CsgTracer tracer(s, use_float);
    const double alpha_cam = cone_alpha(s, c, cam), alpha_light = cone_alpha(s, c, light);
    Result res;
    for (int i = 0; i < 300; ++i) {
        const Ball& b = c.balls[std::size_t(g.pick(int(c.balls.size())))];
        INFO("seed " << seed << " ray " << i);
        // A camera ray, first on a fresh thread, then after a ray along the
        // edge of its would-be cone: the same entry and the same work.
        const glm::dvec3 d = size * aim(g, cam, b, band, i % 2 == 1 && !use_float);
        const render::TraceRay ray{cam, d, 0, kInf};
        render::TraceScratch fresh, primed;
        render::TraceHit ignored;
        tracer.intersect(render::TraceRay{cam, turned_away(d, cam, b.c, edge * alpha_cam), 0, kInf}, ignored, primed);
        const std::uint64_t built = primed.cones.built;
        res.hits += camera_ray_agrees(s, tracer, ray, fresh, primed, 14, h);
        res.in_primed += primed.cones.built == built && built > 0;
        // A shadow ray from a point near a ball (outside the solid) to the
        // light, as shading makes it (unit d, tfar the distance), after a
        // ray ending at the light from a cone's edge: blocked exactly when
        // its first entry comes before the light.
        ShadowRay sr;
        if (!shadow_ray(g, s, tracer, light, b, band, i % 2 == 0 && !use_float, size, 8, 16, h * size, fresh, sr))
            continue;
        const glm::dvec3 o = sr.o, dir = sr.dir;
        const double dist = sr.dist, te = sr.te;
        render::TraceScratch shadow;
        const glm::dvec3 away = turned_away(-dir, light, b.c, edge * alpha_light);
        const glm::dvec3 o2 = light + dist * glm::normalize(away);
        const double dist2 = glm::length(light - o2);
        (void)tracer.occluded(render::TraceRay{o2, (light - o2) / dist2, 0, dist2}, shadow);
        const std::uint64_t built2 = shadow.cones.built;
        CHECK(tracer.occluded(render::TraceRay{o, dir, 0, dist}, shadow) == (te < dist));
        res.in_primed += shadow.cones.built == built2 && built2 > 0;
        res.shadows += te < dist;
    }
    return res;
}

}  // namespace

TEST_CASE("ray cones: camera and shadow rays grazing a crowd at a cone's edge keep every entry and shadow",
          "[render][oracle]") {
    Result r;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const Result x = check(seed, glm::dvec3(0.0), 1, 1e-7, false, 1 - 3e-6);
        r.hits += x.hits, r.shadows += x.shadows, r.in_primed += x.in_primed;
    }
    CHECK(r.hits > 400);
    CHECK(r.shadows > 100);
    CHECK(r.in_primed > 1500);  // the rays did use the cone built before them
}

TEST_CASE("ray cones inside their cones, tiny, huge, far from the origin and in float keep every entry too",
          "[render][oracle]") {
    const glm::dvec3 far = 1e6 * glm::normalize(glm::dvec3(0.4, -1, 0.3));
    const struct {
        std::uint64_t seed;
        glm::dvec3 at;
        double size, h, edge;
        bool use_float;
    } cases[] = {{11, glm::dvec3(0.0), 1, 1e-7, 0.5, false},   {12, glm::dvec3(0.0), 1e-4, 1e-7, 1 - 3e-6, false},
                 {13, glm::dvec3(0.0), 1e4, 1e-7, 1 - 3e-6, false}, {14, far, 1, 1e-6, 1 - 3e-6, false},
                 {15, glm::dvec3(0.0), 1, 1e-4, 1 - 3e-6, true}};
    for (const auto& k : cases) {
        INFO("case " << k.seed);
        const Result x = check(k.seed, k.at, k.size, k.h, k.use_float, k.edge);
        CHECK(x.hits > 100);
        CHECK(x.in_primed > 400);
    }
}

// A thread's cones belong to the tracer that built them: a scratch kept
// across tracers (the second built where the first, now freed, may have
// stood) must not hand the second scene the first one's unit lists. Two
// different crowds from one camera; each camera ray on the second tracer
// with the first's primed scratch gives the fresh scratch's entry.
TEST_CASE("ray cones are not reused across tracers", "[render][oracle]") {
    RandomCsg g1(21), g2(22);
    const Crowd c1 = crowd(g1, glm::dvec3(0.0), 1), c2 = crowd(g2, glm::dvec3(0.0), 1);
    auto scene = [](const Crowd& c) {
        csg::Scene s = make_scene(c.tree);
        s.camera.position = glm::dvec3(1.5, -6, 2.5);
        s.camera.look_at = glm::dvec3(0.0);
        s.lights[0].position = glm::dvec3(-5, -8, 10);
        return s;
    };
    const csg::Scene s1 = scene(c1), s2 = scene(c2);
    const glm::dvec3 cam = s1.camera.position;
    int differ = 0, hits = 0;
    for (int i = 0; i < 200; ++i) {
        const Ball& b = c2.balls[std::size_t(g2.pick(int(c2.balls.size())))];
        const glm::dvec3 d = aim(g2, cam, b, 1e-2, false);
        const render::TraceRay ray{cam, d, 0, kInf};
        render::TraceScratch kept, fresh;
        render::TraceHit h1, h2, h3;
        {
            const auto first = std::make_unique<render::CsgTracer>(s1, false);
            first->intersect(ray, h1, kept);
        }
        const auto second = std::make_unique<render::CsgTracer>(s2, false);
        const bool a = second->intersect(ray, h2, kept), b2 = second->intersect(ray, h3, fresh);
        INFO("ray " << i);
        CHECK(a == b2);
        differ += a != b2 || (a && h2.t != h3.t);
        hits += b2;
        CHECK(is_first_entry(s2, cam, d, b2 ? h3.t : kInf, 14, 1e-7));
    }
    CHECK(differ == 0);
    CHECK(hits > 100);
}

// Two-level cones (ray_cones.hpp): a crowd of more than 256 units of one
// size lists wide cones from every unit and the rays' narrow cones from a
// wide one, each keyed by its own bound on where its rays can reach a unit
// (ray_cones.cpp, cone_key); a ray's cone is its cell's in a grid of
// directions. Camera rays and shadow rays ending at the light on a thread
// whose cones earlier rays built, against point membership and against a
// fresh thread (the same entry and work: the cone is the ray's own); and
// the cones themselves against closed forms on each unit's sphere.
namespace {

// The bounds a narrow cone around `axis` from apex p (half-angle alpha)
// keeps, by closed forms on each unit's sphere: along the cone's direction
// nearest the sphere's centre (the cone's edge, 1e-4 of alpha inside, or
// the centre's own), a listed unit's sphere is entered no nearer than its
// key, and an unlisted unit's sphere is missed. Returns the failures.
int cone_bound_failures(const Crowd& c, const render::RayCone& cone, const glm::dvec3& p, double alpha) {
    std::vector<double> key(c.units.size(), -1);
    for (const render::ConeUnit& u : cone.units) key.at(u.item) = u.key;
    int bad = 0;
    for (std::size_t k = 0; k < c.units.size(); ++k) {
        const Ball& b = c.units[k];
        const glm::dvec3 w = b.c - p;
        const double theta = std::acos(std::clamp(glm::dot(glm::normalize(w), cone.axis), -1.0, 1.0));
        glm::dvec3 v = glm::normalize(w);
        if (theta > alpha * (1 - 1e-4)) {
            const glm::dvec3 e = glm::normalize(w - glm::dot(w, cone.axis) * cone.axis);
            const double a = alpha * (1 - 1e-4);
            v = std::cos(a) * cone.axis + std::sin(a) * e;
        }
        const double tc = glm::dot(w, v), q2 = glm::dot(w, w) - tc * tc;
        const bool hits = q2 < b.r * b.r && tc > 0;
        const double entry = tc - std::sqrt(std::max(0.0, b.r * b.r - q2));
        if (key[k] < -0.5 ? hits : hits && entry < key[k] - 1e-12 * glm::length(w)) {
            UNSCOPED_INFO("unit " << k << " listed " << (key[k] >= -0.5) << " key " << key[k] << " entry " << entry);
            ++bad;
        }
    }
    return bad;
}

struct LevelResult {
    int hits = 0, shadows = 0, narrow = 0, bound_failures = 0;
};

LevelResult check_levels(std::uint64_t seed, const glm::dvec3& at, double size, double h, bool use_float, int rays) {
    const double band = use_float ? 1e-2 : 1e-4;
    RandomCsg g(seed);
    const Crowd c = crowd(g, at, size, 320, glm::dvec3(3, 3, 1.5));
    const csg::Scene s = crowd_scene(c, at, size * glm::dvec3(3, -16, 7), size * glm::dvec3(-10, -14, 20));
    const glm::dvec3 cam = s.camera.position, light = s.lights[0].position;
    const render::CsgTracer tracer(s, use_float);
    render::TraceScratch kept;  // primed by every earlier ray
    LevelResult res;
    for (int i = 0; i < rays; ++i) {
        const Ball& b = c.balls[std::size_t(g.pick(int(c.balls.size())))];
        INFO("seed " << seed << " ray " << i);
        const glm::dvec3 d = size * aim(g, cam, b, band, i % 2 == 1 && !use_float);
        const render::TraceRay ray{cam, d, 0, kInf};
        render::TraceScratch fresh;
        res.hits += camera_ray_agrees(s, tracer, ray, fresh, kept, 40, h);
        // A shadow ray from a point off the crowd's surface to the light
        // (unit d, tfar the distance): blocked exactly when the solid's
        // first entry along it comes before the light.
        ShadowRay sr;
        if (!shadow_ray(g, s, tracer, light, b, band, i % 2 == 0 && !use_float, size, 20, 36, h * size, fresh, sr))
            continue;
        CHECK(tracer.occluded(render::TraceRay{sr.o, sr.dir, 0, sr.dist}, kept) == (sr.te < sr.dist));
        res.shadows += sr.te < sr.dist;
        if (i % 25 == 24) {
            // The narrow cones the rays built so far (cone.apex 0: the camera).
            for (const render::RayCone& cone : kept.cones.cones[1]) {
                if (cone.owner == 0) continue;
                const glm::dvec3 apex = cone.apex == 0 ? cam : light;
                res.bound_failures += cone_bound_failures(c, cone, apex, cone_alpha(s, c, apex, 0.25));
            }
        }
    }
    for (const render::RayCone& cone : kept.cones.cones[1]) res.narrow += cone.owner != 0 && cone.level == 1;
    return res;
}

}  // namespace

TEST_CASE("two-level ray cones: camera and shadow rays grazing a crowd of 320 units keep every entry and shadow",
          "[render][oracle]") {
    const glm::dvec3 far = 1e6 * glm::normalize(glm::dvec3(0.4, -1, 0.3));
    const struct {
        std::uint64_t seed;
        glm::dvec3 at;
        double size, h;
        bool use_float;
        int rays;
    } cases[] = {{1, glm::dvec3(0.0), 1, 1e-7, false, 400}, {2, glm::dvec3(0.0), 1, 1e-7, false, 400},
                 {3, glm::dvec3(0.0), 1e-4, 1e-7, false, 150}, {4, glm::dvec3(0.0), 1e4, 1e-7, false, 150},
                 {5, far, 1, 1e-6, false, 150},                {6, glm::dvec3(0.0), 1, 1e-4, true, 150}};
    for (const auto& k : cases) {
        INFO("case " << k.seed);
        const LevelResult x = check_levels(k.seed, k.at, k.size, k.h, k.use_float, k.rays);
        CHECK(x.hits > k.rays / 3);
        CHECK(x.shadows > k.rays / 10);
        CHECK(x.narrow > 4);  // the rays did go through narrow cones
        CHECK(x.bound_failures == 0);
    }
}

// Ray cones for crowds whose ball sizes spread over orders of magnitude
// (render/tracer/ray_cones.hpp; the spiral family): two levels whose angle
// follows the balls most rays meet, and cones that would list too many
// units (the tiny balls crowding the spiral's centre) marked full, their
// rays sent to the BVH. A spiral of hollow cells shrinking by a constant
// factor per cell (radii over three orders of magnitude, 600 and 4,500
// units), camera rays from the camera and shadow rays ending at the light,
// aimed within ±0.01 % of a cell's sphere (float: 1 %), on a thread whose
// cones every earlier ray built: the entry by point membership, the shadow
// by the first entry, the same entry and work as on a fresh thread; and
// every narrow cone listed (not full) by closed forms on each unit's
// sphere. At unit size, 1e-4, 1e4, 1e6 from the origin and in float.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "render/tracer/tracer.hpp"
#include "tests/render/random_csg.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Sphere {
    glm::dvec3 c;
    double r;
};

// Cell k: a sphere of radius size·q^k at 3·size·q^k from `at`, turned 12
// degrees per cell about z (q = 1e-3^(1/n): the last cell 1e-3 of the
// first), minus one or two smaller spheres inside it (sometimes a box too).
struct Spiral {
    Tree tree = op(Op::Union, {});
    std::vector<Sphere> cells, aims;  // the cells' spheres; every sphere (to aim at)
};

Spiral spiral(RandomCsg& g, const glm::dvec3& at, double size, int n) {
    Spiral s;
    const double q = std::pow(1e-3, 1.0 / n);
    for (int k = 0; k < n; ++k) {
        const double r = size * std::pow(q, k), a = 0.2094395102393195 * k;
        const glm::dvec3 p = at + 3 * r * glm::dvec3(std::cos(a), std::sin(a), g.uni(-0.2, 0.2));
        const glm::dmat4 m = translate(p.x, p.y, p.z) * rotate_deg(g.uni(0, 360), glm::dvec3(0, 0, 1));
        s.cells.push_back({p, r});
        s.aims.push_back({p, r});
        std::vector<Tree> kids{leaf(sphere(r, m))};
        for (int h = 1 + g.pick(2); h > 0; --h) {
            const double ri = g.uni(0.8, 0.97) * r;
            const glm::dvec3 off = g.uni(-0.02, 0.02) * r * glm::dvec3(1, g.uni(-1, 1), g.uni(-1, 1));
            kids.push_back(leaf(sphere(ri, m * translate(off.x, off.y, off.z))));
            s.aims.push_back({glm::dvec3(m * glm::dvec4(off, 1)), ri});
        }
        if (g.pick(4) == 0) kids.push_back(leaf(box(glm::dvec3(0.5 * r), glm::dvec3(2 * r), m)));  // a corner cut
        s.tree.kids.push_back(op(Op::Difference, kids));
    }
    return s;
}

// The narrow cones' half-angle around apex p as build_apexes chooses it for
// spread sizes: a quarter of spread_radius (the radius at which half the
// sum of the radii is reached, largest first) over the distance to the
// middle of the units' boxes.
double narrow_alpha(const csg::Scene& s, const Spiral& sp, const glm::dvec3& p) {
    std::vector<double> r;
    for (const Sphere& c : sp.cells) r.push_back(c.r);
    std::sort(r.begin(), r.end());
    double total = 0, acc = 0, rw = r[0];
    for (double x : r) total += x;
    for (std::size_t i = r.size(); i-- > 0;)
        if ((acc += r[i]) >= 0.5 * total) {
            rw = r[i];
            break;
        }
    csg::Aabb box;
    for (std::uint32_t k = 0; k < s.nodes[s.root].count; ++k) box.extend(s.nodes[s.children[s.nodes[s.root].first + k]].bounds);
    return std::clamp(0.25 * rw / glm::length(0.5 * (box.lo + box.hi) - p), 1e-3, 0.25);
}

// Closed forms on each cell's sphere for a listed narrow cone around
// `axis` (half-angle alpha) from p: along the cone's direction nearest the
// centre (its edge, 1e-4 of alpha inside, or the centre's own), a listed
// unit's sphere is entered no nearer than its key, an unlisted one missed.
int listing_failures(const Spiral& sp, const render::RayCone& cone, const glm::dvec3& p, double alpha) {
    std::vector<double> key(sp.cells.size(), -1);
    for (const render::ConeUnit& u : cone.units) key.at(u.item) = u.key;
    int bad = 0;
    for (std::size_t k = 0; k < sp.cells.size(); ++k) {
        const glm::dvec3 w = sp.cells[k].c - p;
        const double r = sp.cells[k].r, theta = std::acos(std::clamp(glm::dot(glm::normalize(w), cone.axis), -1.0, 1.0));
        glm::dvec3 v = glm::normalize(w);
        if (theta > alpha * (1 - 1e-4)) {
            const glm::dvec3 e = glm::normalize(w - glm::dot(w, cone.axis) * cone.axis);
            v = std::cos(alpha * (1 - 1e-4)) * cone.axis + std::sin(alpha * (1 - 1e-4)) * e;
        }
        const double tc = glm::dot(w, v), q2 = glm::dot(w, w) - tc * tc;
        const bool hits = q2 < r * r && tc > 0;
        const double entry = tc - std::sqrt(std::max(0.0, r * r - q2));
        if (key[k] < -0.5 ? hits : hits && entry < key[k] - 1e-12 * glm::length(w)) {
            UNSCOPED_INFO("unit " << k << " listed " << (key[k] >= -0.5) << " key " << key[k] << " entry " << entry);
            ++bad;
        }
    }
    return bad;
}

struct Tally {
    int hits = 0, shadows = 0, listing_failures = 0;
    int listed = 0, full = 0;  // narrow cones seen in the thread's slots (every 25 rays)
};

Tally check(std::uint64_t seed, const glm::dvec3& at, double size, double h, bool use_float, int n, int rays) {
    const double band = use_float ? 1e-2 : 1e-4;
    RandomCsg g(seed);
    const Spiral sp = spiral(g, at, size, n);
    csg::Scene s = make_scene(sp.tree);
    s.camera.position = at + size * glm::dvec3(6, -9, 8);
    s.camera.look_at = at;
    s.lights[0].position = at + size * glm::dvec3(4, -6, 10);
    const glm::dvec3 cam = s.camera.position, light = s.lights[0].position;
    const render::CsgTracer tracer(s, use_float);
    render::TraceScratch kept;  // primed by every earlier ray
    Tally t;
    for (int i = 0; i < rays; ++i) {
        // Half the rays at the largest 10 % of the cells (most of the
        // image), half at any sphere (the centre's crowd: full cones).
        const std::size_t pick = i % 2 ? std::size_t(g.pick(int(sp.aims.size())))
                                       : std::size_t(g.pick(int(sp.aims.size()) / 10));
        const Sphere& b = sp.aims[pick];
        const glm::dvec3 u = glm::normalize(glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) + 1e-3);
        const glm::dvec3 d = size * glm::normalize(b.c + g.uni(1 - band, 1 + band) * b.r * u - cam);
        INFO("seed " << seed << " ray " << i << " sphere " << pick);
        render::TraceScratch fresh;
        render::TraceHit hit, hit2;
        const bool found = tracer.intersect(render::TraceRay{cam, d, 0, kInf}, hit, fresh);
        const std::uint64_t tests = kept.counters.interval_tests;
        const bool found2 = tracer.intersect(render::TraceRay{cam, d, 0, kInf}, hit2, kept);
        CHECK(found == found2);
        CHECK((found ? hit.t : kInf) == (found2 ? hit2.t : kInf));
        CHECK(fresh.counters.interval_tests == kept.counters.interval_tests - tests);
        CHECK(is_first_entry(s, cam, d, found ? hit.t : kInf, 30, h));
        t.hits += found;
        // A shadow ray from 1-3 sizes before the sphere (outside the solid)
        // to the light: blocked exactly when the first entry along it comes
        // before the light.
        const glm::dvec3 ds = glm::normalize(b.c + g.uni(1 - band, 1 + band) * b.r * u - light);
        const glm::dvec3 o = light + (glm::length(b.c - light) + size * g.uni(-3, 3)) * ds;
        if (csg_contains(s, o)) continue;
        const double dist = glm::length(light - o);
        const glm::dvec3 dir = (light - o) / dist;
        render::TraceHit entry;
        const double te = tracer.intersect(render::TraceRay{o, dir, 0, kInf}, entry, fresh) ? entry.t : kInf;
        CHECK(is_first_entry(s, o, dir, te, dist, h * size));
        CHECK(tracer.occluded(render::TraceRay{o, dir, 0, dist}, kept) == (te < dist));
        t.shadows += te < dist;
        if (i % 25 == 24 || i == rays - 1)
            for (const render::RayCone& cone : kept.cones.cones[1]) {
                if (cone.owner == 0) continue;
                t.full += cone.full;
                if (cone.full) continue;
                t.listed += !cone.units.empty();
                const glm::dvec3 apex = cone.apex == 0 ? cam : light;
                t.listing_failures += listing_failures(sp, cone, apex, narrow_alpha(s, sp, apex));
            }
    }
    return t;
}

}  // namespace

TEST_CASE("ray cones over a spiral of cells of spread sizes keep every entry and shadow, full cones too",
          "[render][oracle]") {
    const glm::dvec3 far = 1e6 * glm::normalize(glm::dvec3(0.4, -1, 0.3));
    const struct {
        std::uint64_t seed;
        glm::dvec3 at;
        double size, h;
        bool use_float;
        int n, rays;
    } cases[] = {{1, glm::dvec3(0.0), 1, 1e-7, false, 600, 200}, {2, glm::dvec3(0.0), 1e-4, 1e-7, false, 600, 100},
                 {3, glm::dvec3(0.0), 1e4, 1e-7, false, 600, 100}, {4, far, 1, 1e-6, false, 600, 100},
                 {5, glm::dvec3(0.0), 1, 1e-4, true, 600, 100},    {6, glm::dvec3(0.0), 1, 1e-7, false, 4500, 30}};
    for (const auto& k : cases) {
        INFO("case " << k.seed);
        const Tally x = check(k.seed, k.at, k.size, k.h, k.use_float, k.n, k.rays);
        CHECK(x.hits > k.rays / 2);
        CHECK(x.shadows > k.rays / 10);
        CHECK(x.listed > 0);  // rays went through listed narrow cones
        CHECK(x.full > 0);    // and through full ones, to the BVH
        CHECK(x.listing_failures == 0);
    }
}

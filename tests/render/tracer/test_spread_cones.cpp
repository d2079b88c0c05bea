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
#include <random>
#include <vector>

#include "render/tracer/tracer.hpp"
#include "render/tracer/unit_balls.hpp"
#include "tests/render/random_csg.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

using Sphere = render::Ball;  // a centre and a radius
const double kInf = std::numeric_limits<double>::infinity();

// Cell k: a sphere of radius size·q^k at 3·size·q^k from `at`, turned 12
// degrees per cell about z (q = 1e-3^(1/n) unless given: the last cell
// 1e-3 of the first), minus one or two smaller spheres inside it
// (sometimes a box too).
struct Spiral {
    Tree tree = op(Op::Union, {});
    std::vector<Sphere> cells, aims;  // the cells' spheres; every sphere (to aim at)
};

Spiral spiral(RandomCsg& g, const glm::dvec3& at, double size, int n, double q = 0) {
    Spiral s;
    if (q == 0) q = std::pow(1e-3, 1.0 / n);
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

// A ring of 128 large cells (radius 0.75-1 size, 6 from `at`) round a
// cluster of 472 small ones (0.05 size down by 0.99 a cell, within 0.15 of
// `at`): seen through the ring, the cluster's outline is exposed.
Spiral ring_and_cluster(RandomCsg& g, const glm::dvec3& at, double size) {
    Spiral s;
    for (int k = 0; k < 600; ++k) {
        const double a = 0.049 * k;
        const double r = size * (k < 128 ? 1 - 0.002 * k : 0.05 * std::pow(0.99, k - 128));
        const glm::dvec3 p = at + size * (k < 128 ? 6.0 * glm::dvec3(std::cos(a), std::sin(a), 0)
                                                  : 0.15 * glm::dvec3(g.uni(-1, 1), g.uni(-1, 1), g.uni(-1, 1)) / std::sqrt(3.0));
        const glm::dmat4 m = translate(p.x, p.y, p.z);
        s.cells.push_back({p, r});
        s.tree.kids.push_back(op(Op::Difference, {leaf(sphere(r, m)), leaf(sphere(0.9 * r, m * translate(0, 0, 0.05 * r)))}));
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

// How many of `samples` rays through the quad of corner rays (o, d) hit
// (two of them its corners).
int hits_in_quad(const render::CsgTracer& tracer, render::TraceScratch& scratch, const glm::dvec3 (&o)[4],
                 const glm::dvec3 (&d)[4], int samples, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> w(0, 1);
    int hits = 0;
    for (int k = 0; k < samples; ++k) {
        const double a = k == 0 ? 0 : k == 1 ? 1 : w(rng), b = k < 2 ? double(k) : w(rng);
        const double wt[4] = {(1 - a) * (1 - b), a * (1 - b), a * b, (1 - a) * b};
        glm::dvec3 ro(0.0), rd(0.0);
        for (int i = 0; i < 4; ++i) ro += wt[i] * o[i], rd += wt[i] * d[i];
        render::TraceHit hit;
        hits += tracer.intersect(render::TraceRay{ro, rd, 0, kInf}, hit, scratch);
    }
    return hits;
}

}  // namespace

TEST_CASE("ray cones over a spiral of cells of spread sizes keep every entry and shadow, full cones too",
          "[render][oracle]") {
    const glm::dvec3 far = 1e6 * glm::normalize(glm::dvec3(0.4, -1, 0.3));
    struct Case { std::uint64_t seed; glm::dvec3 at; double size, h; bool use_float; int n, rays; };
    const Case cases[] = {{1, glm::dvec3(0.0), 1, 1e-7, false, 600, 200}, {2, glm::dvec3(0.0), 1e-4, 1e-7, false, 600, 100},
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

// Culling a crowd of spread sizes (render/tracer/spread_cull.cpp): the
// scene's pinhole camera's tiles ask the 128 largest cells' balls and one
// ball round the other 472 (ring_and_cluster: the merged ball's outline
// exposed). Tiles of corner rays from the camera, half of them tiny (1e-9
// to 0.1 of a cell's radius) and just inside or outside the outline of one
// of the merged cells that reach farthest from their centroid, on the far
// side (1e-8 to 0.1 of its radius: the merged ball's edge), each split into
// four blocks that ask only the tile's list: every culled quad's sampled
// rays miss (intersect), at unit size, 1e-3, 1e4 and 1e6 from the origin.
TEST_CASE("a crowd of spread sizes is culled by its largest cells and one ball round the rest",
          "[render][cull]") {
    const glm::dvec3 far = 1e6 * glm::normalize(glm::dvec3(0.4, -1, 0.3));
    const struct {
        double s;
        glm::dvec3 at;
    } cases[] = {{1, glm::dvec3(0.0)}, {1e-3, {5e-3, -3e-3, 2e-3}}, {1e4, {2e4, 0, -1e4}}, {1, far}};
    for (const auto& c : cases) {
        RandomCsg g(31);
        const Spiral sp = ring_and_cluster(g, c.at, c.s);
        csg::Scene s = make_scene(sp.tree);
        s.camera.position = c.at + c.s * glm::dvec3(6, -9, 8);
        s.camera.look_at = c.at;
        const glm::dvec3 eye = s.camera.position;
        const render::CsgTracer tracer(s, false);
        REQUIRE(tracer.cull_unit_count() == 129);
        // The merged cells (the 472 smallest) and the six that reach
        // farthest from their centroid.
        glm::dvec3 centroid(0.0);
        for (std::size_t k = 128; k < 600; ++k) centroid += sp.cells[k].c / 472.0;
        std::vector<std::size_t> outer(472);
        for (std::size_t k = 0; k < 472; ++k) outer[k] = 128 + k;
        const auto reach = [&](std::size_t k) { return glm::length(sp.cells[k].c - centroid) + sp.cells[k].r; };
        std::partial_sort(outer.begin(), outer.begin() + 6, outer.end(),
                          [&](std::size_t x, std::size_t y) { return reach(x) > reach(y); });
        outer.resize(6);
        render::TraceScratch scratch;
        std::mt19937_64 rng(17);
        std::uniform_real_distribution<double> u(-1, 1), w(0, 1);
        std::vector<std::uint32_t> tile(129), block(129);
        int culled = 0, kept = 0, alone = 0;
        for (int q = 0; q < 1500; ++q) {
            glm::dvec3 target = c.at + c.s * glm::dvec3(4 * u(rng), 4 * u(rng), 0.5 * u(rng));
            double size = 0.01 + 0.1 * w(rng);
            if (q % 4 >= 2) {
                // Round the outline of one of the merged cells that reach
                // farthest from their centroid, on the far side from it:
                // where the merged ball's edge lies.
                const Sphere& b = sp.cells[outer[std::size_t(q) % outer.size()]];
                const glm::dvec3 view = glm::normalize(b.c - eye), away = b.c - centroid;
                glm::dvec3 side = away - glm::dot(away, view) * view;
                side = glm::normalize(side + 0.3 * glm::length(side) * glm::dvec3(u(rng), u(rng), u(rng)));
                const double gap = (q % 8 < 5 ? 1 : -1) * std::pow(10.0, -8 + 7 * w(rng));
                // The tangent direction from the eye, leaning out by gap.
                const double sin_b = std::min(1.0, b.r * (1 + gap) / glm::length(b.c - eye));
                target = eye + std::sqrt(1 - sin_b * sin_b) * view + sin_b * side;
                size = std::pow(10.0, -9 + 8 * w(rng)) * b.r / c.s;
            }
            const glm::dvec3 aim = glm::normalize(target - eye), across = glm::normalize(glm::cross(aim, {0, 0, 1}));
            const auto dir = [&](double x, double y) {
                return glm::normalize(aim + 0.4 * size * ((x - 0.5) * across + (y - 0.5) * glm::cross(across, aim)));
            };
            glm::dvec3 o[4] = {eye, eye, eye, eye};
            glm::dvec3 d[4] = {dir(0, 0), dir(1, 0), dir(1, 1), dir(0, 1)};
            const int ntile = tracer.near_units(o, d, nullptr, 0, tile.data());
            REQUIRE(ntile >= 0);
            CHECK((ntile == 0) == tracer.misses_all(o, d));
            alone += ntile == 1 && tile[0] == 128;  // the merged ball only
            // The tile itself (part 0), then its four blocks, which ask only
            // the tile's list.
            for (int part = 0; part < 5; ++part) {
                const double e = part == 0 ? 1 : 0.5, x0 = part == 0 ? 0 : e * ((part - 1) % 2),
                             y0 = part == 0 ? 0 : e * ((part - 1) / 2);
                const glm::dvec3 corners[4] = {dir(x0, y0), dir(x0 + e, y0), dir(x0 + e, y0 + e), dir(x0, y0 + e)};
                std::copy(corners, corners + 4, d);
                const bool listed = part == 0 ? ntile > 0 : ntile > 0 && tracer.near_units(o, d, tile.data(), ntile, block.data()) > 0;
                kept += listed;
                culled += !listed;
                INFO("scale " << c.s << " quad " << q << " part " << part);
                if (!listed) CHECK(hits_in_quad(tracer, scratch, o, d, 24, rng) == 0);
            }
        }
        INFO("scale " << c.s << ": " << culled << " culled, " << kept << " kept, " << alone << " tiles near the merged ball alone");
        CHECK(culled > 1000);
        CHECK(alone > 50);
        CHECK(kept > 1000);
    }
}

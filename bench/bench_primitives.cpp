// Nanoseconds per ray–primitive test (intersect_leaf through the kind switch,
// as the renderer calls it), per primitive, hit and miss, float and double.
// Rays are pre-generated (seeded) near each solid and sorted into hits and
// misses by the double solve; a benchmark iteration is one test.
//   build/bench/bench_primitives --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "render/primitives/primitives.hpp"
#include "render/primitives/lathe.hpp"
#include "render/primitives/prism.hpp"
#include "render/primitives/prism_grid.hpp"

namespace {

using kerf::csg::Leaf;
using kerf::csg::PrimKind;
using glm::dvec3;

struct Shape {
    const char* name;
    PrimKind kind;
    double p[6];
    dvec3 centre;
    double radius;  // rays aim within 1.5x this ball
};

const Shape kShapes[] = {
    {"sphere", PrimKind::Sphere, {1, 0, 0, 0, 0, 0}, dvec3(0), 1},
    {"box", PrimKind::Box, {-0.5, -0.5, -0.5, 0.5, 0.5, 0.5}, dvec3(0), 0.87},
    {"cylinder", PrimKind::Cylinder, {0, 1, 0.5, 0.5, 0, 0}, dvec3(0, 0, 0.5), 0.71},
    {"cone", PrimKind::Cylinder, {0, 1, 0.5, 0, 0, 0}, dvec3(0, 0, 0.5), 0.71},
    {"torus", PrimKind::Torus, {1, 0.25, 0, 0, 0, 0}, dvec3(0), 1.25},
    {"torus_thin", PrimKind::Torus, {1, 1e-3, 0, 0, 0, 0}, dvec3(0), 1.001},
    {"plane", PrimKind::Plane, {0, 0, 1, 0, 0, 0}, dvec3(0), 1},
    {"paraboloid", PrimKind::Paraboloid, {1, 0.7, 0, 0, 0, 0}, dvec3(0, 0, 0.5), 0.86},
    {"hyperboloid", PrimKind::Hyperboloid, {1, 0.6, 0.3, 0, 0, 0}, dvec3(0), 0.78},
};

struct RaySet {
    std::vector<dvec3> o, d;
};

// 1024 rays of the wanted kind (hit: at least one span), from 2 to 5 radii away.
RaySet make_rays(const Leaf& leaf, const Shape& s, bool want_hit, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    auto unit = [&] {
        for (;;) {
            const dvec3 v(u(rng), u(rng), u(rng));
            const double l = glm::length(v);
            if (l > 1e-2 && l <= 1) return v / l;
        }
    };
    RaySet set;
    for (int tries = 0; set.o.size() < 1024 && tries < 10000000; ++tries) {
        const dvec3 aim = s.centre + 1.5 * s.radius * unit() * std::cbrt(0.5 * (u(rng) + 1));
        const dvec3 dir = unit();
        const dvec3 o = aim - (2 + 1.5 * (u(rng) + 1)) * s.radius * dir;
        kerf::csg::Span<double> spans[kerf::csg::kMaxSpans];
        const bool hit = kerf::csg::intersect_leaf<double>(leaf, o, dir, spans) > 0;
        if (hit == want_hit) {
            set.o.push_back(o);
            set.d.push_back(dir);
        }
    }
    return set;
}

template <typename T>
void run(benchmark::State& state, Leaf leaf, RaySet rays) {
    using V = glm::vec<3, T>;
    std::vector<V> o(rays.o.begin(), rays.o.end()), d(rays.d.begin(), rays.d.end());
    const std::size_t mask = o.size() - 1;  // 1024 rays
    std::size_t i = 0;
    kerf::csg::Span<T> spans[kerf::csg::kMaxSpans];
    for (auto _ : state) {
        const int n = kerf::csg::intersect_leaf<T>(leaf, o[i], d[i], spans);
        benchmark::DoNotOptimize(n);
        benchmark::DoNotOptimize(spans);
        i = (i + 1) & mask;
    }
}

// Prism leaves (intersect_prism): a regular n-gon section of circumradius
// 0.5 times 0 < z < 1, with n = 4 (the box's shape), 32 … 10,000 edges, and
// a 1000-edge star (a gear profile's worth of crossings per ray). Each
// without a grid (every edge tested) and with one of `cells` cells per edge
// (render/primitives/prism_grid.hpp; "/gridC" in the name).
kerf::csg::Polygon2 ngon(int n, bool star) {
    kerf::csg::Polygon2 p;
    std::vector<glm::dvec2> v;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * (i + 0.5) / n, r = star && i % 2 ? 0.4 : 0.5;
        v.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    for (int i = 0; i < n; ++i) p.edges.emplace_back(v[i].x, v[i].y, v[(i + 1) % n].x, v[(i + 1) % n].y);
    p.lo = glm::dvec2(-0.5);
    p.hi = glm::dvec2(0.5);
    return p;
}

template <typename T>
void run_prism(benchmark::State& state, kerf::csg::Polygon2 poly, RaySet rays, kerf::csg::PrismGrid grid) {
    using V = glm::vec<3, T>;
    std::vector<V> o(rays.o.begin(), rays.o.end()), d(rays.d.begin(), rays.d.end());
    const double p[6] = {0, 1, 0, 0, 0, 0};
    std::vector<kerf::csg::PrismSpan<T>> spans(kerf::csg::prism_span_room(poly.edges.size()));
    std::vector<kerf::csg::PrismCrossing<T>> scratch(poly.edges.size());
    const std::size_t mask = o.size() - 1;
    std::size_t i = 0;
    for (auto _ : state) {
        const int n = kerf::csg::intersect_prism<T>(poly, p, o[i], d[i], spans.data(), scratch.data(),
                                                    -std::numeric_limits<T>::infinity(),
                                                    std::numeric_limits<T>::infinity(), &grid);
        benchmark::DoNotOptimize(n);
        benchmark::DoNotOptimize(spans.data());
        i = (i + 1) & mask;
    }
}

// 1024 rays drawn around `around` (its box leaf `box`) whose hit-or-miss by
// `hits` is `hit`; empty when too few are found.
template <class Hits>
RaySet sorted_rays(const Leaf& box, const Shape& around, bool hit, std::uint64_t seed, const Hits& hits) {
    RaySet all = make_rays(box, around, true, seed), more = make_rays(box, around, false, seed + 1);
    all.o.insert(all.o.end(), more.o.begin(), more.o.end());
    all.d.insert(all.d.end(), more.d.begin(), more.d.end());
    RaySet rays;
    for (std::size_t k = 0; k < all.o.size() && rays.o.size() < 1024; ++k)
        if (hits(all.o[k], all.d[k]) == hit) {
            rays.o.push_back(all.o[k]);
            rays.d.push_back(all.d[k]);
        }
    while (!rays.o.empty() && rays.o.size() < 1024) {  // power of two for the index mask
        rays.o.push_back(rays.o[rays.o.size() % 512]);
        rays.d.push_back(rays.d[rays.d.size() % 512]);
    }
    if (rays.o.size() != 1024) rays = {};
    return rays;
}

const bool prisms_registered = [] {
    std::uint64_t seed = 100;
    const Shape around{"prism", PrimKind::Box, {-0.5, -0.5, 0, 0.5, 0.5, 1}, dvec3(0, 0, 0.5), 0.87};
    struct Case { const char* name; int n; bool star; std::vector<double> cells; };
    for (const Case& c : {Case{"prism4", 4, false, {}}, Case{"prism16", 16, false, {2}}, Case{"prism32", 32, false, {2}},
                          Case{"prism64", 64, false, {2}}, Case{"prism128", 128, false, {2}},
                          Case{"prism1000", 1000, false, {0.5, 1, 2, 4, 8}}, Case{"prism1000_star", 1000, true, {1, 2, 4}},
                          Case{"prism10000", 10000, false, {2}}}) {
        const kerf::csg::Polygon2 poly = ngon(c.n, c.star);
        // Hit or miss by the prism itself: rays are drawn around its box and sorted by intersect_prism.
        Leaf box;
        box.kind = PrimKind::Box;
        for (int k = 0; k < 6; ++k) box.p[k] = around.p[k];
        for (bool hit : {true, false}) {
            const double p[6] = {0, 1, 0, 0, 0, 0};
            std::vector<kerf::csg::PrismSpan<double>> sp(kerf::csg::prism_span_room(poly.edges.size()));
            std::vector<kerf::csg::PrismCrossing<double>> sc(poly.edges.size());
            const RaySet rays = sorted_rays(box, around, hit, seed, [&](const dvec3& o, const dvec3& d) {
                return kerf::csg::intersect_prism<double>(poly, p, o, d, sp.data(), sc.data()) > 0;
            });
            seed += 2;
            if (rays.o.empty()) continue;
            const std::string base = std::string(c.name) + (hit ? "/hit" : "/miss");
            benchmark::RegisterBenchmark((base + "/float").c_str(), run_prism<float>, poly, rays, kerf::csg::PrismGrid{});
            benchmark::RegisterBenchmark((base + "/double").c_str(), run_prism<double>, poly, rays, kerf::csg::PrismGrid{});
            for (double cells : c.cells) {
                const kerf::csg::PrismGrid grid = kerf::csg::build_prism_grid(poly, 0, cells);
                char tag[32];
                std::snprintf(tag, sizeof tag, "/grid%g", cells);
                benchmark::RegisterBenchmark((base + tag + "/float").c_str(), run_prism<float>, poly, rays, grid);
                benchmark::RegisterBenchmark((base + tag + "/double").c_str(), run_prism<double>, poly, rays, grid);
            }
        }
    }
    return true;
}();

// Lathe leaves (intersect_lathe): the profile of a tube (a 4-edge
// rectangle, radius 0.3 … 0.5, 0 < z < 1) and a 32-gon ring (a torus-like
// profile of radius 0.15 around (0.35, 0.5)), rays around the box of both.
template <typename T>
void run_lathe(benchmark::State& state, kerf::csg::Polygon2 poly, RaySet rays) {
    using V = glm::vec<3, T>;
    std::vector<V> o(rays.o.begin(), rays.o.end()), d(rays.d.begin(), rays.d.end());
    std::vector<kerf::csg::PrismSpan<T>> spans(kerf::csg::lathe_span_room(poly.edges.size()));
    std::vector<kerf::csg::PrismCrossing<T>> scratch(kerf::csg::lathe_crossing_room(poly.edges.size()));
    const std::size_t mask = o.size() - 1;
    std::size_t i = 0;
    for (auto _ : state) {
        const int n = kerf::csg::intersect_lathe<T>(poly, o[i], d[i], spans.data(), scratch.data());
        benchmark::DoNotOptimize(n);
        benchmark::DoNotOptimize(spans.data());
        i = (i + 1) & mask;
    }
}

const bool lathes_registered = [] {
    std::uint64_t seed = 200;
    const Shape around{"lathe", PrimKind::Box, {-0.5, -0.5, 0, 0.5, 0.5, 1}, dvec3(0, 0, 0.5), 0.87};
    Leaf box;
    box.kind = PrimKind::Box;
    for (int k = 0; k < 6; ++k) box.p[k] = around.p[k];
    kerf::csg::Polygon2 tube;
    tube.edges = {{0.3, 0, 0.5, 0}, {0.5, 0, 0.5, 1}, {0.5, 1, 0.3, 1}, {0.3, 1, 0.3, 0}};
    tube.lo = {0.3, 0}, tube.hi = {0.5, 1};
    kerf::csg::Polygon2 ring = ngon(32, false);
    for (glm::dvec4& e : ring.edges) e = e * 0.3 + glm::dvec4(0.35, 0.5, 0.35, 0.5);
    ring.lo = {0.2, 0.35}, ring.hi = {0.5, 0.65};
    for (const auto& [name, poly] : {std::pair{"lathe4", tube}, std::pair{"lathe32", ring}}) {
        for (bool hit : {true, false}) {
            std::vector<kerf::csg::PrismSpan<double>> sp(kerf::csg::lathe_span_room(poly.edges.size()));
            std::vector<kerf::csg::PrismCrossing<double>> sc(kerf::csg::lathe_crossing_room(poly.edges.size()));
            const kerf::csg::Polygon2& section = poly;
            const RaySet rays = sorted_rays(box, around, hit, seed, [&](const dvec3& o, const dvec3& d) {
                return kerf::csg::intersect_lathe<double>(section, o, d, sp.data(), sc.data()) > 0;
            });
            seed += 2;
            if (rays.o.empty()) continue;
            const std::string base = std::string(name) + (hit ? "/hit" : "/miss");
            benchmark::RegisterBenchmark((base + "/float").c_str(), run_lathe<float>, poly, rays);
            benchmark::RegisterBenchmark((base + "/double").c_str(), run_lathe<double>, poly, rays);
        }
    }
    return true;
}();

const bool registered = [] {
    std::uint64_t seed = 1;
    for (const Shape& s : kShapes) {
        Leaf leaf;
        leaf.kind = s.kind;
        for (int k = 0; k < 6; ++k) leaf.p[k] = s.p[k];
        for (bool hit : {true, false}) {
            RaySet rays = make_rays(leaf, s, hit, seed++);
            if (rays.o.size() != 1024) continue;  // e.g. a plane is hit by almost every ray
            const std::string base = std::string(s.name) + (hit ? "/hit" : "/miss");
            benchmark::RegisterBenchmark((base + "/float").c_str(), run<float>, leaf, rays);
            benchmark::RegisterBenchmark((base + "/double").c_str(), run<double>, leaf, rays);
        }
    }
    return true;
}();

// The torus as a grooved solid asks for it (torus.cpp clips to the window):
// a ray that enters a groove meets the tube with the window starting at
// the minuend's entry, inside the tube, and running on to the minuend's
// exit; only the tube's exit (and any later crossing in the window) is
// solved. R = 1, r = 0.1 (the reference grooved sphere's r/R); rays from
// 2 to 5 radii away aimed inside the tube, the window from the middle of
// the first span to 1.5 radii past the aim point.
template <typename T>
void run_window(benchmark::State& state, Leaf leaf, RaySet rays, std::vector<double> wa, std::vector<double> wb) {
    using V = glm::vec<3, T>;
    std::vector<V> o(rays.o.begin(), rays.o.end()), d(rays.d.begin(), rays.d.end());
    const std::size_t mask = o.size() - 1;
    std::size_t i = 0;
    kerf::csg::Span<T> spans[kerf::csg::kMaxSpans];
    for (auto _ : state) {
        const int n = kerf::csg::intersect_leaf<T>(leaf, o[i], d[i], spans, T(wa[i]), T(wb[i]));
        benchmark::DoNotOptimize(n);
        benchmark::DoNotOptimize(spans);
        i = (i + 1) & mask;
    }
}

const bool windows_registered = [] {
    Leaf leaf;
    leaf.kind = PrimKind::Torus;
    leaf.p[0] = 1;
    leaf.p[1] = 0.1;
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> u(-1, 1);
    RaySet rays;
    std::vector<double> wa, wb;
    while (rays.o.size() < 1024) {
        const double phi = M_PI * u(rng);
        const dvec3 v(u(rng), u(rng), u(rng));
        if (!(glm::dot(v, v) <= 1)) continue;
        const dvec3 aim = dvec3(std::cos(phi), std::sin(phi), 0) + 0.09 * v;
        dvec3 dir(u(rng), u(rng), u(rng));
        if (!(glm::dot(dir, dir) > 1e-4 && glm::dot(dir, dir) <= 1)) continue;
        dir = glm::normalize(dir);
        const double back = 2 + 1.5 * (u(rng) + 1);
        const dvec3 o = aim - back * dir;
        kerf::csg::Span<double> spans[kerf::csg::kMaxSpans];
        if (kerf::csg::intersect_leaf<double>(leaf, o, dir, spans) == 0) continue;
        rays.o.push_back(o);
        rays.d.push_back(dir);
        wa.push_back(0.5 * (spans[0].t0 + spans[0].t1));
        wb.push_back(back + 1.5);
    }
    benchmark::RegisterBenchmark("torus_groove/window/float", run_window<float>, leaf, rays, wa, wb);
    benchmark::RegisterBenchmark("torus_groove/window/double", run_window<double>, leaf, rays, wa, wb);
    return true;
}();

}  // namespace

BENCHMARK_MAIN();

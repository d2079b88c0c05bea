// Nanoseconds per ray–primitive test (intersect_leaf through the kind switch,
// as the renderer calls it), per primitive, hit and miss, float and double.
// Rays are pre-generated (seeded) near each solid and sorted into hits and
// misses by the double solve; a benchmark iteration is one test.
//   build/bench/bench_primitives --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "render/primitives/primitives.hpp"

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

}  // namespace

BENCHMARK_MAIN();

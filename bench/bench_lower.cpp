// Lowering speed: a scene graph of 1,000,000 leaves built directly
// (no parser), lowered several times; prints the median and the peak RSS.
//   bench_lower [leaves=1000000] [runs=5]
// Shape: a for-loop-like top-level union of translated "parts", each part a
// difference of a box minus a sphere, a cylinder, a torus and a scaled
// sphere wrapped in a union — so lowering flattens, composes transforms,
// computes five kinds of exact boxes and tests subtrahends against minuends.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "csg/huge_pages.hpp"
#include "lower/lower.hpp"

using namespace kerf;
using graph::NodeKind;
using csg::PrimKind;

namespace {

struct Builder {
    graph::SceneGraph g;
    SourceLoc loc{std::make_shared<SourceFile>(SourceFile{"bench.sdl", ""}), 1, 1};

    std::uint32_t add(NodeKind k, std::initializer_list<std::uint32_t> kids, std::uint32_t index = 0) {
        graph::Node n;
        n.kind = k;
        n.index = index;
        n.first_child = static_cast<std::uint32_t>(g.child_refs.size());
        n.child_count = static_cast<std::uint32_t>(kids.size());
        g.child_refs.insert(g.child_refs.end(), kids);
        n.loc = loc;
        g.nodes.push_back(n);
        return static_cast<std::uint32_t>(g.nodes.size() - 1);
    }
    std::uint32_t prim(PrimKind k, std::initializer_list<double> p, std::uint32_t line) {
        graph::Node n;
        n.kind = NodeKind::Primitive;
        n.prim = k;
        std::copy(p.begin(), p.end(), n.p);
        n.loc = loc;
        n.loc.line = line;
        g.nodes.push_back(n);
        return static_cast<std::uint32_t>(g.nodes.size() - 1);
    }
    std::uint32_t xform(const glm::dmat4& m, std::uint32_t child) {
        g.matrices.push_back(m);
        return add(NodeKind::Transform, {child}, static_cast<std::uint32_t>(g.matrices.size() - 1));
    }
};

graph::SceneGraph build(std::size_t leaves) {
    Builder b;
    const std::size_t parts = leaves / 5;
    std::vector<std::uint32_t> top;
    top.reserve(parts);
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(parts))));
    for (std::size_t i = 0; i < parts; ++i) {
        const auto box = b.prim(PrimKind::Box, {-1, -1, -1, 1, 1, 1}, 2);
        const auto ball = b.prim(PrimKind::Sphere, {1.2}, 3);
        const auto cyl = b.prim(PrimKind::Cylinder, {-2, 2, 0.4, 0.4}, 4);
        const auto tor = b.xform(glm::rotate(glm::dmat4(1), 0.3, glm::dvec3(1, 0, 0)), b.prim(PrimKind::Torus, {1, 0.2}, 5));
        const auto small = b.xform(glm::scale(glm::dmat4(1), glm::dvec3(0.5, 0.7, 2)), b.prim(PrimKind::Sphere, {0.5}, 6));
        const auto cut = b.add(NodeKind::Union, {cyl, tor, small});
        const auto part = b.add(NodeKind::Difference, {box, ball, cut});
        const glm::dvec3 at(3.0 * double(i % side), 3.0 * double(i / side), 0);
        top.push_back(b.xform(glm::rotate(glm::translate(glm::dmat4(1), at), 0.01 * double(i), glm::dvec3(0, 0, 1)), part));
    }
    graph::Node root;
    root.kind = NodeKind::Union;
    root.first_child = static_cast<std::uint32_t>(b.g.child_refs.size());
    root.child_count = static_cast<std::uint32_t>(top.size());
    b.g.child_refs.insert(b.g.child_refs.end(), top.begin(), top.end());
    b.g.nodes.push_back(root);
    b.g.root = static_cast<std::uint32_t>(b.g.nodes.size() - 1);
    return std::move(b.g);
}

double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

// user + system time of this (single-threaded) process
double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Baseline for the first run: lowering must write ~0.55 GB of new memory
// (leaves, temporary and final nodes); on a virtual machine the first touch
// of fresh pages alone can cost a large part of a second.
void fresh_memory_baseline(std::size_t bytes) {
    const double c0 = cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    {
        std::vector<char> block;
        block.reserve(bytes);
        csg::advise_huge_pages(block.data(), bytes);
        std::memset(block.data(), 1, bytes);
        asm volatile("" : : "r"(block.data()) : "memory");
    }
    const auto t1 = std::chrono::steady_clock::now();
    std::printf("baseline: writing %.0f MB of fresh memory: %.3f s wall, %.3f s CPU\n", double(bytes) / 1048576.0,
                std::chrono::duration<double>(t1 - t0).count(), cpu_seconds() - c0);
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t leaves = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1'000'000;
    const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
    const graph::SceneGraph graph = build(leaves);
    std::printf("graph: %zu nodes, peak RSS after building it %.0f MB\n", graph.nodes.size(), peak_rss_mb());
    fresh_memory_baseline(leaves * (sizeof(csg::Leaf) + 72 + sizeof(csg::Node)) * 6 / 5);
    std::vector<double> times, cpu;
    std::size_t lowered_leaves = 0, lowered_nodes = 0;
    for (int r = 0; r < runs; ++r) {
        const double c0 = cpu_seconds();
        const auto t0 = std::chrono::steady_clock::now();
        csg::Scene s = lower_to_csg(graph);
        const auto t1 = std::chrono::steady_clock::now();
        const double c1 = cpu_seconds();
        times.push_back(std::chrono::duration<double>(t1 - t0).count());
        cpu.push_back(c1 - c0);
        std::printf("  run %d: %.3f s wall, %.3f s CPU\n", r + 1, times.back(), cpu.back());
        lowered_leaves = s.leaves.size();
        lowered_nodes = s.nodes.size();
    }
    std::sort(times.begin(), times.end());
    std::sort(cpu.begin(), cpu.end());
    std::printf("lower_to_csg: %zu leaves, %zu nodes; median %.3f s (min %.3f, max %.3f) over %d runs\n",
                lowered_leaves, lowered_nodes, times[times.size() / 2], times.front(), times.back(), runs);
    std::printf("CPU time (user+sys, immune to other processes on the machine): median %.3f s\n", cpu[cpu.size() / 2]);
    std::printf("peak RSS %.0f MB\n", peak_rss_mb());
    return 0;
}

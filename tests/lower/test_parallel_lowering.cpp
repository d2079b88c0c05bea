// A wide union's leaves are placed by several threads (lower/flat_tree.cpp,
// place_run; lower/parallel_indices.hpp): the lowered scene must be the
// serial walk's bit for bit, and an error the serial walk's, whatever the
// thread count (docs/performance.md, "Lowering and the tracer's build on two
// threads").
#include <catch2/catch.hpp>

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <string>

#include "csg/dump.hpp"
#include "lower/lower.hpp"
#include "lower/parallel_indices.hpp"
#include "tests/lower/graph_builder.hpp"

using namespace kerf;

namespace {

// Every field of the scene the renderer reads, as text and as leaf bits.
void check_same(const csg::Scene& a, const csg::Scene& b) {
    CHECK(csg::dump_scene(a) == csg::dump_scene(b));
    REQUIRE(a.leaves.size() == b.leaves.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.leaves.size(); ++i)
        differ += std::memcmp(&a.leaves[i], &b.leaves[i], sizeof(csg::Leaf)) != 0;
    CHECK(differ == 0);
    CHECK(a.sources.size() == b.sources.size());
    for (std::size_t i = 0; i < std::min(a.sources.size(), b.sources.size()); ++i)
        CHECK(a.sources[i].line == b.sources[i].line);
}

csg::Scene lowered(const graph::SceneGraph& g, unsigned threads) {
    LowerOptions o;
    o.threads = threads;
    return lower_to_csg(g, o);
}

// `n` children of one union: runs of leaves of every sort the parallel
// path takes (translated and bare primitives, rotated ones, duplicates, a
// shared sphere node, meshes with no points whose leaves are dropped)
// broken now and then by a child it does not take (a nested union).
graph::SceneGraph wide_union(int n, bool under_frame) {
    // Runs of 999, 1700 (serial: under kParallelRun), 2700, 2700, 2700, ~1200.
    const auto breaks = [](int k) { return k == 0 || k == 111 || k == 300 || k == 600 || k == 900 || k == 1200; };
    test::GraphBuilder b;
    b.g.meshes.push_back(graph::PolygonMesh{});  // no points: an empty box
    const std::uint32_t shared = b.sphere(0.25);
    std::vector<std::uint32_t> kids;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 at(i % 37, (i / 37) % 41, i / (37 * 41));
        switch (i % 9) {
            case 0: kids.push_back(b.translate(at, b.sphere(0.4))); break;
            case 1: kids.push_back(b.sphere(0.5)); break;  // all at the origin: duplicates
            case 2: kids.push_back(b.translate(at, b.cube(0.3))); break;
            case 3: kids.push_back(b.translate(at, b.mesh(0))); break;
            case 4: kids.push_back(b.rotate(30 + i, {0, 0, 1}, b.torus(0.3, 0.1))); break;
            case 5: kids.push_back(b.translate(at, shared)); break;
            case 6: kids.push_back(b.translate(glm::dvec3(-0.0, 0.0, -0.0), b.sphere(0.4))); break;
            case 7: kids.push_back(b.translate(at, b.cylinder(0, 1, 0.2, 0.1))); break;
            default:
                if (breaks(i / 9)) kids.push_back(b.uni({b.translate(at, b.sphere(0.3)), b.cube(0.1)}));
                else kids.push_back(b.translate(at * 0.5, b.sphere(0.4)));
        }
    }
    std::uint32_t top = b.uni(kids);
    if (under_frame) top = b.color({0.2, 0.4, 0.6}, b.scale({1, 2, -0.5}, top));
    b.g.root = b.uni({top, b.sphere(3)});
    return b.g;
}

}  // namespace

TEST_CASE("a wide union lowers to the same scene on 1, 2 and 3 threads") {
    for (const bool framed : {false, true}) {
        INFO("under a frame: " << framed);
        const graph::SceneGraph g = wide_union(12000, framed);
        const csg::Scene serial = lowered(g, 1);
        // The runs' leaves were deduplicated and their empty ones dropped.
        CHECK(serial.leaves.size() < 12000);
        CHECK(serial.leaves.size() > 7000);  // of ~10,700 operands (> kParallelDuplicates) before deduplication
        for (const unsigned threads : {2u, 3u}) {
            INFO("threads: " << threads);
            check_same(serial, lowered(g, threads));
        }
    }
}

TEST_CASE("a wide union's first error in child order is the one reported, whatever the thread count") {
    test::GraphBuilder b;
    std::vector<std::uint32_t> kids;
    for (int i = 0; i < 6000; ++i) {
        // Out of range (docs/spec.md's coordinate limit) at two children.
        const double x = (i == 1234 || i == 5000) ? 1e300 : double(i);
        kids.push_back(b.translate({x, 0, 0}, b.sphere(0.5)));
    }
    b.g.root = b.uni(kids);
    std::string serial, parallel;
    try {
        lowered(b.g, 1);
    } catch (const std::exception& e) {
        serial = e.what();
    }
    try {
        lowered(b.g, 2);
    } catch (const std::exception& e) {
        parallel = e.what();
    }
    REQUIRE(!serial.empty());
    CHECK(parallel == serial);
}

TEST_CASE("for_each_index visits every index once and rethrows the lowest index's exception") {
    for (const unsigned threads : {1u, 2u, 4u}) {
        std::vector<std::atomic<int>> seen(10000);
        lowering::for_each_index(seen.size(), 7, threads, [&](std::size_t i) { ++seen[i]; });
        std::size_t wrong = 0;
        for (auto& s : seen) wrong += s.load() != 1;
        CHECK(wrong == 0);
        // Chunks of one index: the high ones are often done (and fail) first.
        for (int round = 0; round < 20; ++round) {
            std::string what;
            try {
                lowering::for_each_index(3000, 1, threads, [&](std::size_t i) {
                    if (i == 2999 || i == 1500 || i == 40) throw std::runtime_error(std::to_string(i));
                });
            } catch (const std::runtime_error& e) {
                what = e.what();
            }
            CHECK(what == "40");
        }
    }
}

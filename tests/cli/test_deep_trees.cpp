// Deep operation trees (docs/lowering.md, "Depth"): the tracer recurses once
// per level, so lowering refuses a tree deeper than csg::kMaxDepth with a
// located error and render() gives its threads the stack the depth needs.
// Through the real binary: a stack overflow is a signal, which these tests
// tell from an exit code.
#include <catch2/catch.hpp>

#include "csg/scene.hpp"
#include "tests/cli/run_kerf.hpp"

namespace {

// An alternating intersection/difference chain: two levels per call. The
// spheres grow outwards and barely move, so every ray reaches the bottom.
std::string alternating(int calls) {
    return "module m(n) { if (n > 0) intersection() { sphere(2 + n * 1e-4); difference() { sphere(2 + n * 1e-4); "
           "translate([1e-5, 0, 0]) m(n - 1); } } else sphere(0.5); }\nm(" + std::to_string(calls) + ");\n";
}

// Nested differences, each with ten more subtrahends, so every level has
// its own Embree BVH and the query nests inside Embree's traversal (the
// deepest stack per level, ~10 KB).
std::string wide_differences(int calls) {
    return "module m(n) { if (n > 0) difference() { sphere(2 + n * 1e-4); for (i = [0:9]) "
           "translate([2 * cos(36 * i), 2 * sin(36 * i), 0]) sphere(0.3); translate([1e-5, 0, 0]) m(n - 1); } "
           "else sphere(0.5); }\nm(" + std::to_string(calls) + ");\n";
}

// Nested intersections of differences with forty thin slabs each: a ray's
// window over a difference crosses more subtrahends than its box grid lists
// (32), so the query goes through the difference's own BVH, which is
// committed by that first query (Accel::ready) -- here at every level, the
// last one at the bottom of the deepest recursion (1,995 commits at 3,991
// levels, counted with a debugger on Accel::commit_now).
std::string slabbed(int calls) {
    return "module m(n) { if (n > 0) intersection() { sphere(2 + n * 1e-4); difference() { sphere(2 + n * 1e-4); "
           "for (i = [0:39]) translate([0, 0, -1.95 + i * 0.1]) cube([10, 10, 0.001], center = true); "
           "translate([1e-5, 0, 0]) m(n - 1); } } else sphere(0.5); }\nm(" + std::to_string(calls) + ");\n";
}

const std::string kLimits = " --max-call-depth 100000";

}  // namespace

TEST_CASE("a CSG tree deeper than kMaxDepth is a located error, not a crash") {
    static_assert(kerf::csg::kMaxDepth == 4000, "the scripts below are sized for it");
    auto dir = test_dir("deep_refused");
    const std::string alt = write_file(dir / "alt.sdl", alternating(15000));  // 30,001 levels
    for (const char* command : {"check", "dump", "render"}) {
        auto r = run_kerf_bounded(std::string(command) + " '" + alt + "' -o '" + (dir / "a.png").string() + "'" +
                                      (std::string(command) == "render" ? " -W 8 -H 6" : "") + kLimits,
                                  dir);
        INFO(command << ": " << r.err);
        CHECK(r.status == 1);
        CHECK(first_line(r.err).find(alt + ":1:") == 0);
        CHECK(first_line(r.err).find(": error: the CSG tree is deeper than 4000 levels here") != std::string::npos);
        CHECK(r.out.empty());
    }
    std::string nested = "module m(n) { if (n > 0) difference() { sphere(2); m(n - 1); } else sphere(1); }\nm(24000);\n";
    auto r = run_kerf_bounded("render '" + write_file(dir / "nested.sdl", nested) + "' -W 8 -H 6 -o '" +
                                  (dir / "n.png").string() + "'" + kLimits,
                              dir);
    CHECK(r.status == 1);
    CHECK(first_line(r.err).find((dir / "nested.sdl").string() + ":1:") == 0);
}

TEST_CASE("a CSG tree just below kMaxDepth renders") {
    auto dir = test_dir("deep_renders");
    // The stack is under test, not the look: --look plain keeps the
    // 16 shadow rays of the studio's soft key out of the time bound.
    // 3,991 levels (1995 calls of two, and the leaf).
    auto r = run_kerf_bounded("render '" + write_file(dir / "alt.sdl", alternating(1995)) + "' -W 6 -H 4 -o '" +
                                  (dir / "alt.png").string() + "' --threads 2 --look plain" + kLimits,
                              dir, 120);
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(std::filesystem::file_size(dir / "alt.png") > 0);
    // 3,991 levels, each through Embree (the largest stack per level).
    r = run_kerf_bounded("render '" + write_file(dir / "wide.sdl", wide_differences(3990)) + "' -W 16 -H 12 -o '" +
                             (dir / "wide.png").string() + "' --threads 2 --look plain" + kLimits,
                         dir, 120);
    INFO(r.err);
    CHECK(r.status == 0);
    // 3,991 levels, each difference's BVH built by its first query, deep in
    // the recursion (the stack budget's base covers Embree's build there).
    r = run_kerf_bounded("render '" + write_file(dir / "slabbed.sdl", slabbed(1995)) + "' -W 3 -H 3 --aa off -o '" +
                             (dir / "slabbed.png").string() + "' --threads 2 --look plain" + kLimits,
                         dir, 120);
    INFO(r.err);
    CHECK(r.status == 0);
}

// RenderOptions::cancel (render.hpp): a render whose flag is set stops at the
// next tile and throws RenderCancelled, for `kerf view` (docs/spec.md §13),
// and one whose flag stays clear is the same image as without a flag.
#include <catch2/catch.hpp>

#include <atomic>
#include <cstring>

#include "render/render.hpp"
#include "tests/render/scene_builder.hpp"

using namespace kerf;
using namespace kerf::test;
using csg::Op;

namespace {

csg::Scene ball() {
    csg::Scene s = make_scene(leaf(sphere(1.0, glm::dmat4(1.0), 0)), {csg::Material{}});
    s.camera.position = {0, -5, 1};
    return s;
}

}  // namespace

TEST_CASE("a render cancelled before it starts throws and traces nothing", "[render][cancel]") {
    std::atomic<bool> cancel{true};
    render::RenderOptions o;
    o.width = 64;
    o.height = 64;
    o.cancel = &cancel;
    int calls = 0;
    CHECK_THROWS_AS(render::render(ball(), o, nullptr, [&](double) { ++calls; }), render::RenderCancelled);
    CHECK(calls == 0);  // not even progress(0): the flag is read once the BVHs are built
}

TEST_CASE("a render cancelled after its first tile skips the remaining tiles", "[render][cancel]") {
    std::atomic<bool> cancel{false};
    for (render::RenderOptions o : {render::RenderOptions{}, [] { render::RenderOptions a; a.adaptive = true; return a; }()}) {
        cancel = false;
        o.width = 320;  // 10 x 8 tiles of 32 pixels
        o.height = 256;
        o.threads = 1;  // tiles strictly one after another: exactly one finishes
        o.cancel = &cancel;
        int tiles = 0;
        CHECK_THROWS_AS(render::render(ball(), o, nullptr,
                                       [&](double f) {
                                           if (f == 0) return;  // BVHs built, tracing starts
                                           ++tiles;
                                           cancel = true;
                                       }),
                        render::RenderCancelled);
        CHECK(tiles == 1);
    }
}

TEST_CASE("a clear cancel flag changes no pixel", "[render][cancel]") {
    std::atomic<bool> cancel{false};
    render::RenderOptions o;
    o.width = 80;
    o.height = 60;
    const render::Image plain = render::render(ball(), o);
    o.cancel = &cancel;
    const render::Image flagged = render::render(ball(), o);
    REQUIRE(plain.pixels.size() == flagged.pixels.size());
    CHECK(std::memcmp(plain.pixels.data(), flagged.pixels.data(), plain.pixels.size() * sizeof(float)) == 0);
}

// Shared by the lower tests that start from script text: the lowered scene
// of a script, and a pixel-by-pixel comparison of two depth AOVs.
#pragma once
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>

#include "interpreter/interpreter.hpp"
#include "lower/geometry_ops.hpp"
#include "lower/lower.hpp"
#include "render/image/image.hpp"

namespace kerf::test {

// The evaluated script, as a file `path` (its extension picks the dialect).
inline EvalResult evaluated(const std::string& text, const std::string& path = "test.sdl") {
    auto f = std::make_shared<SourceFile>();
    f->path = path;
    f->text = text;
    EvalOptions o;
    o.resolve_geometry_ops = resolve_geometry_ops;  // as the CLI: projection() of a hull
    return evaluate_source(f, o);
}

inline csg::Scene lowered(const std::string& text) { return lower_to_csg(evaluated(text).graph); }
inline csg::Scene lowered_as(const std::string& text, const std::string& path) {
    return lower_to_csg(evaluated(text, path).graph);
}

// Hit where `want` hits, at the same depth within `rel`; enough hits to mean something.
inline void same_depth(const render::Image& got, const render::Image& want, double rel, std::size_t min_hits = 200) {
    REQUIRE(got.pixels.size() == want.pixels.size());
    std::size_t hits = 0;
    for (std::size_t i = 0; i < want.pixels.size(); ++i) {
        INFO("pixel " << i);
        REQUIRE(std::isfinite(got.pixels[i]) == std::isfinite(want.pixels[i]));
        if (!std::isfinite(want.pixels[i])) continue;
        ++hits;
        CHECK(got.pixels[i] == Approx(want.pixels[i]).epsilon(rel));
    }
    CHECK(hits > min_hits);
}

}  // namespace kerf::test

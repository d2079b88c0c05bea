// --quality draft|good|final (docs/quality.md "Presets"): each preset is the
// same render as its documented knobs spelled out, `good` is the defaults,
// an explicit knob beside a preset wins, and a bad name is a usage error.
// The oracle is the explicit command line, not a picture of the preset.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

TEST_CASE("each --quality preset renders the bytes of its documented knobs, and explicit knobs override it") {
    auto dir = test_dir("quality_presets");
    // Two mirrors facing each other: the reflection depth shows in the pixels.
    write_file(dir / "s.sdl",
               "camera(position = [0, -6, 2], look_at = [0, 0, 0]);\nlight([3, -4, 5], radius = 0.5);\n"
               "material(color = \"silver\", reflect = 0.9) { translate([-1.2, 0, 0]) cube([0.2, 3, 3], center = true);\n"
               "  translate([1.2, 0, 0]) cube([0.2, 3, 3], center = true); }\nsphere(0.6);\n");
    auto render = [&](const std::string& out, const std::string& flags) {
        const auto r = run_kerf("render '" + (dir / "s.sdl").string() + "' -o '" + (dir / out).string() + "' -W 24 -H 18 " + flags, dir);
        INFO(flags << "\n" << r.err);
        REQUIRE(r.status == 0);
        return slurp(dir / out);
    };
    const std::string plain = render("plain.ppm", "");
    CHECK(render("good.ppm", "--quality good") == plain);
    const std::string draft = render("draft.ppm", "--quality draft");
    CHECK(draft == render("draft_knobs.ppm", "--aa-samples 4 --aa-threshold 0.1 --max-depth 2"));
    CHECK(draft != plain);
    const std::string final_ = render("final.ppm", "--quality final");
    CHECK(final_ == render("final_knobs.ppm", "--aa-samples 64 --aa-threshold 0.02 --max-depth 8"));
    CHECK(final_ != plain);
    // Explicit knobs win, in either order: --spp turns the preset's
    // adaptive knobs off without an error; --max-depth replaces its depth.
    CHECK(render("draft_spp.ppm", "--quality draft --spp 2") == render("spp_d2.ppm", "--spp 2 --max-depth 2"));
    CHECK(render("final_depth.ppm", "--max-depth 4 --quality final --aa-samples 16") ==
          render("final_depth_knobs.ppm", "--aa-threshold 0.02"));
    // The path tracer's share of a preset: its paths per pixel and bounces.
    CHECK(render("path_draft.ppm", "--integrator path --quality draft") ==
          render("path_draft_knobs.ppm", "--integrator path --spp 16 --max-depth 8"));
    CHECK(render("path_draft_spp.ppm", "--integrator path --quality draft --spp 2") ==
          render("path_spp.ppm", "--integrator path --spp 2 --max-depth 8"));
}

TEST_CASE("a bad --quality is a one-line usage error, wherever render options go") {
    auto dir = test_dir("quality_bad");
    for (const char* cmd : {"render", "watch", "view"}) {
        const auto r = run_kerf(std::string(cmd) + " x.sdl --quality best", dir);
        INFO(cmd);
        CHECK(r.status == 2);
        CHECK(first_line(r.err) == "kerf: error: --quality expects draft, good or final, got 'best'");
    }
    const auto missing = run_kerf("render x.sdl --quality", dir);
    CHECK(missing.status == 2);
    CHECK(first_line(missing.err) == "kerf: error: --quality needs a value");
    const auto measure = run_kerf("measure x.sdl --quality draft", dir);
    CHECK(measure.status == 2);
    CHECK(first_line(measure.err) == "kerf: error: measure writes no image; --quality does not apply to it");
}

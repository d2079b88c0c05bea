// `kerf assemble` (docs/farm.md): bands rendered by separate processes,
// with other thread counts, join into exactly the bytes of a single
// render (the oracle: that render's file); bands that do not belong
// together are exit 2 with one line and the output is left untouched.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "tests/cli/farm_scene.hpp"

namespace fs = std::filesystem;

namespace {

// Bands 0..n-1 of the farm scene, each by its own kerf process; returns
// their quoted paths, in the order given by `order` (default: reversed, so
// assemble must sort them itself).
std::string render_bands(const fs::path& dir, const std::string& out, int n, const std::string& args,
                         const char* threads = "1") {
    std::string paths;
    for (int k = n - 1; k >= 0; --k) {
        render_farm_scene(dir, args + " --threads " + threads + " --tile " + std::to_string(k) + "/" +
                                   std::to_string(n) + " -o " + quoted(dir, out + ".png"));
        paths += " " + quoted(dir, out + "_tile" + (n > 10 && k < 10 ? "0" : "") + std::to_string(k) + "of" +
                                       std::to_string(n) + ".png");
    }
    return paths;
}

KerfRun assemble(const fs::path& dir, const std::string& out, const std::string& tiles) {
    return run_kerf("assemble " + quoted(dir, out) + tiles, dir);
}

}  // namespace

TEST_CASE("assembled bands are byte-identical to a single render") {
    auto dir = test_dir("assemble_bytes");
    write_file(dir / "scene.sdl", kFarmScene);
    const struct {
        const char* args;
        int bands;
    } cases[] = {
        {"-W 64 -H 48", 4},                            // adaptive anti-aliasing, the default
        {"-W 61 -H 47", 5},                            // bands of unequal height
        {"-W 40 -H 12 --spp 4 --seed 7", 12},          // jittered samples, one row per band
        {"-W 50 -H 40 --preview -D '$t=0.3'", 3},      // preview, a frame of the animation
        {"-W 48 -H 32 --aa-threshold 0.02 --precision float", 2},
        {"-W 24 -H 64 --preview", 4},                  // edges on the 16-row pieces: every piece reused
        {"-W 24 -H 100 --preview", 3},                 // pieces of two bands re-encoded
    };
    for (const auto& c : cases) {
        INFO(c.args << ", " << c.bands << " bands");
        render_farm_scene(dir, std::string(c.args) + " --threads 2 -o " + quoted(dir, "single.png"));
        const std::string tiles = render_bands(dir, "part", c.bands, c.args);
        const KerfRun r = assemble(dir, "joined.png", tiles);
        INFO(r.err);
        REQUIRE(r.status == 0);
        CHECK(slurp(dir / "joined.png") == slurp(dir / "single.png"));
    }
    // Any 8-bit format: the same encoder is handed the same bytes.
    render_farm_scene(dir, "-W 64 -H 48 -o " + quoted(dir, "single.jpg"));
    const KerfRun r = assemble(dir, "joined.jpg", render_bands(dir, "part", 3, "-W 64 -H 48", "2"));
    REQUIRE(r.status == 0);
    CHECK(slurp(dir / "joined.jpg") == slurp(dir / "single.jpg"));
}

TEST_CASE("bands that do not join are exit 2 with one line, and the output stays as it was") {
    auto dir = test_dir("assemble_errors");
    write_file(dir / "scene.sdl", kFarmScene);
    const std::string base = "-W 40 -H 30";
    render_bands(dir, "a", 3, base);
    render_bands(dir, "scene", 3, base + " -D '$t=0.5'");
    render_bands(dir, "size", 3, "-W 40 -H 31");
    render_bands(dir, "seed", 3, base + " --seed 9");
    render_bands(dir, "opts", 3, base + " --spp 4");
    render_bands(dir, "split", 2, base);
    render_bands(dir, "facets", 3, base + " --facets exact");  // the same scene: it has no $fn
    render_farm_scene(dir, base + " -o " + quoted(dir, "plain.png"));
    render_bands(dir, "old", 3, base);
    hide_pieces_table(dir / "old_tile1of3.png");
    write_file(dir / "text.png", "not a picture");
    const std::string a0 = quoted(dir, "a_tile0of3.png"), a1 = quoted(dir, "a_tile1of3.png"),
                      a2 = quoted(dir, "a_tile2of3.png");
    auto p = [&](const char* name) { return (dir / name).string(); };
    struct Case {
        std::string tiles, error;
    };
    // Band 1 of another render between bands 0 and 2 of a.
    auto foreign = [&](const char* band, const std::string& why) {
        return Case{" " + a0 + " " + quoted(dir, band) + " " + a2,
                    p(band) + " is not a band of the render " + p("a_tile0of3.png") + " belongs to: " + why};
    };
    const Case cases[] = {
        {" " + a0 + " " + a2, "band 1 of 3 is missing"},
        {" " + a0, "bands 1, 2 of 3 are missing"},
        {" " + a0 + " " + a1 + " " + a1 + " " + a2, p("a_tile1of3.png") + " and " + p("a_tile1of3.png") +
                                                        " are both band 1 of 3"},
        foreign("scene_tile1of3.png", "another scene (hash "),
        foreign("size_tile1of3.png", "another size (40x31, not 40x30)"),
        foreign("seed_tile1of3.png", "another seed (9, not 0)"),
        foreign("opts_tile1of3.png",
                "other options (spp:4,double,reflect:4, not aa:16:0.050000000000000003,double,reflect:4)"),
        foreign("split_tile1of2.png", "a split into 2 bands, not 3"),
        foreign("facets_tile1of3.png", "other options (aa:16:0.050000000000000003,double,reflect:4,facets:exact, not "
                                       "aa:16:0.050000000000000003,double,reflect:4)"),
        {" " + a0 + " " + quoted(dir, "plain.png"),
         p("plain.png") + ": not a band of a kerf render (render bands with kerf render --tile K/N)"},
        {" " + a0 + " " + quoted(dir, "text.png"), p("text.png") + ": not a PNG file"},
        {" " + a0 + " " + quoted(dir, "absent.png"), p("absent.png") + ": cannot open it"},
        {" " + a0 + " " + a1 + " " + a2 + " " + quoted(dir, "a_tile0of3.png"),
         p("a_tile0of3.png") + " and " + p("a_tile0of3.png") + " are both band 0 of 3"},
        {" " + a0 + " " + quoted(dir, "old_tile1of3.png") + " " + a2,
         p("old_tile1of3.png") + ": has no table of its image data pieces (render it again with this kerf)"},
    };
    write_file(dir / "out.png", "old");
    for (const auto& c : cases) {
        const KerfRun r = assemble(dir, "out.png", c.tiles);
        INFO(c.tiles);
        CHECK(r.status == 2);
        CHECK(first_line(r.err).rfind("kerf: error: " + c.error, 0) == 0);
        CHECK(r.err.find('\n') == r.err.size() - 1);
        CHECK(slurp(dir / "out.png") == "old");
    }
    // A truncated band: libpng's own words, still one line.
    const std::string whole = slurp(dir / "a_tile1of3.png");
    write_file(dir / "cut.png", whole.substr(0, whole.size() / 2));
    KerfRun r = assemble(dir, "out.png", " " + a0 + " " + quoted(dir, "cut.png") + " " + a2);
    CHECK(r.status == 2);
    CHECK(r.err == "kerf: error: " + p("cut.png") + ": the file ends early\n");
    // The output may not be one of the bands, nor a float format.
    r = assemble(dir, "a_tile0of3.png", " " + a0 + " " + a1 + " " + a2);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write " + p("a_tile0of3.png") + ": it is the input file " + p("a_tile0of3.png") + "\n");
    r = assemble(dir, "out.exr", " " + a0 + " " + a1 + " " + a2);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: bands hold 8-bit sRGB; " + p("out.exr") +
                                   " would store floats (assemble into PNG, JPEG, ...)");
    CHECK_FALSE(fs::exists(dir / "out.exr"));
    CHECK(slurp(dir / "a_tile0of3.png").size() > 100);
}

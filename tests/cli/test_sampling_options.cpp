// Sampling on the command line: adaptive anti-aliasing is the default,
// --spp N is uniform, and a knob that a choice would ignore is a usage error
// (exit 2), never silence.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

TEST_CASE("sampling knobs that would be ignored, and bad integrators, are usage errors") {
    auto dir = test_dir("sampling");
    const struct {
        const char* args;
        const char* error;
    } cases[] = {
        {"--spp 4 --aa auto", "--spp gives uniform sampling; it cannot be combined with --aa auto"},
        {"--spp 4 --aa-samples 8", "--aa-samples applies to adaptive anti-aliasing, which --spp turns off"},
        {"--aa off --aa-threshold 0.1", "--aa-threshold applies to adaptive anti-aliasing, which --aa off turns off"},
        {"--aov depth --spp 4", "--aov traces one ray through each pixel centre; drop --spp"},
        {"--preview --aa-samples 8", "--preview traces one ray through each pixel centre; drop --aa-samples"},
        {"--aa maybe", "--aa expects auto or off, got 'maybe'"},
        {"--aa-threshold 1.5", "--aa-threshold expects a number from 0 to 1, got '1.5'"},
        {"--aa-threshold nan", "--aa-threshold expects a number from 0 to 1, got 'nan'"},
        {"--aa-samples 1", "--aa-samples expects a whole number from 2 to 4096, got '1'"},
        {"--integrator foo", "--integrator expects whitted or path, got 'foo'"},
        {"--integrator path --spp 0", "--spp expects a whole number from 1 to 65536, got '0'"},
        {"--integrator path --aa auto", "--integrator path samples every pixel alike (--spp N, default 64); drop --aa auto"},
        {"--integrator path --aa-samples 8", "--integrator path samples every pixel alike (--spp N, default 64); drop --aa-samples"},
        {"--integrator path --preview", "--preview traces one Whitted ray through each pixel centre; drop --integrator path"},
        {"--integrator path --aov depth", "--aov traces one Whitted ray through each pixel centre; drop --integrator path"},
        {"--integrator path --max-depth 33", "--max-depth expects a whole number from 0 to 32, got '33'"},
        {"--progressive", "--progressive applies to --integrator path, whose paths come in passes"},
        {"--time-limit 5", "--time-limit applies to --integrator path, whose paths come in passes"},
        {"--integrator path --time-limit 0", "--time-limit expects a number of seconds from 1e-9 to 1e7, got '0'"},
        {"--integrator path --progressive -o -", "--progressive writes the image again after every pass; -o - (standard output) is not for it"},
        {"--integrator path --time-limit 5 --tile 0/4",
         "--time-limit does not apply to the farm: its frames and bands must not depend on a machine's speed"},
    };
    for (const auto& c : cases) {
        const auto r = run_kerf(std::string("render x.sdl ") + c.args, dir);
        INFO(c.args);
        CHECK(r.status == 2);
        CHECK(first_line(r.err) == std::string("kerf: error: ") + c.error);
    }
}

TEST_CASE("the default render anti-aliases edges, --aa off and --spp 1 do not") {
    auto dir = test_dir("sampling_default");
    write_file(dir / "s.sdl", "camera(position = [0, -6, 2], look_at = [0, 0, 0]);\nsphere(1);\n");
    const std::string d = "'" + dir.string() + "/";
    const auto on = run_kerf("render " + d + "s.sdl' -o " + d + "on.ppm' -W 64 -H 48 --stats", dir);
    const auto off = run_kerf("render " + d + "s.sdl' -o " + d + "off.ppm' -W 64 -H 48 --stats --aa off", dir);
    const auto one = run_kerf("render " + d + "s.sdl' -o " + d + "one.ppm' -W 64 -H 48 --spp 1", dir);
    REQUIRE(on.status == 0);
    REQUIRE(off.status == 0);
    REQUIRE(one.status == 0);
    CHECK(on.err.find("anti-aliasing: ") != std::string::npos);
    CHECK(off.err.find("anti-aliasing: ") == std::string::npos);
    const auto read = [&](const char* name) {
        std::ifstream f(dir / name, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(f), {});
    };
    CHECK(read("off.ppm") == read("one.ppm"));
    CHECK(read("on.ppm") != read("off.ppm"));
}

TEST_CASE("the path integrator renders 64 paths per pixel unless --spp, and whitted is the default") {
    auto dir = test_dir("integrator_path");
    write_file(dir / "s.sdl", "camera(position = [0, -6, 2], look_at = [0, 0, 0]);\nlight([3, -4, 5], radius = 0.5);\nsphere(1);\n");
    // Renders s.sdl to `out` (16×12) with `flags`; the --stats report.
    auto render = [&](const std::string& out, const std::string& flags) {
        const auto r = run_kerf("render '" + (dir / "s.sdl").string() + "' -o '" + (dir / out).string() + "' -W 16 -H 12 --stats " + flags, dir);
        REQUIRE(r.status == 0);
        return r.err;
    };
    const std::string path = render("p.ppm", "--integrator path"), four = render("p4.ppm", "--integrator path --spp 4");
    render("w.ppm", "--integrator whitted");
    render("d.ppm", "");
    CHECK(slurp(dir / "w.ppm") == slurp(dir / "d.ppm"));
    CHECK(slurp(dir / "p.ppm") != slurp(dir / "w.ppm"));
    // --stats counts primary rays: 64 and 4 per pixel.
    CHECK(path.find("(" + std::to_string(16 * 12 * 64) + " primary") != std::string::npos);
    CHECK(four.find("(" + std::to_string(16 * 12 * 4) + " primary") != std::string::npos);
}

TEST_CASE("the path integrator warns that it ignores ambient_occlusion") {
    auto dir = test_dir("integrator_ao");
    write_file(dir / "s.sdl", "ambient_occlusion(8);\nsphere(1);\n");
    const std::string s = "render '" + (dir / "s.sdl").string() + "' -o '" + (dir / "s.ppm").string() + "' -W 8 -H 6";
    const auto path = run_kerf(s + " --integrator path --spp 1", dir);
    const auto whitted = run_kerf(s, dir);
    CHECK(path.status == 0);
    CHECK(path.err.find("s.sdl:1:1: warning: ambient_occlusion: does not apply to --integrator path") != std::string::npos);
    CHECK(whitted.status == 0);
    CHECK(whitted.err.find("warning") == std::string::npos);
}

TEST_CASE("the path integrator with --progressive writes each pass and ends with the bytes of a plain render") {
    auto dir = test_dir("integrator_progressive");
    write_file(dir / "s.sdl", "camera(position = [0, -6, 2], look_at = [0, 0, 0]);\nlight([3, -4, 5], radius = 0.5);\nsphere(1);\n");
    const std::string s = "render '" + (dir / "s.sdl").string() + "' -W 16 -H 12 --integrator path --spp 8 -o '";
    const auto plain = run_kerf(s + (dir / "plain.png").string() + "'", dir);
    const auto passes = run_kerf(s + (dir / "passes.png").string() + "' --progressive", dir);
    REQUIRE(plain.status == 0);
    REQUIRE(passes.status == 0);
    CHECK(slurp(dir / "plain.png") == slurp(dir / "passes.png"));
    for (const char* line : {"(1 of 8 paths per pixel)", "(2 of 8 paths per pixel)", "(4 of 8 paths per pixel)"})
        CHECK(passes.err.find(line) != std::string::npos);
    CHECK(passes.err.find("(8 of 8") == std::string::npos);  // the last pass is the file itself
    // A limit already spent: the first pass only, and a note saying so.
    const auto limited = run_kerf(s + (dir / "limited.png").string() + "' --time-limit 1e-9", dir);
    CHECK(limited.status == 0);
    CHECK(limited.err.find("limited.png has 1 of 8 paths per pixel") != std::string::npos);
}

// The farm's command line (docs/farm.md): frame numbering and $t, and
// every contradiction or impossible request is exit 2 (or 3 for an output
// that cannot be written) with one line, before anything is written.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include "render/image/png_read.hpp"
#include "tests/cli/farm_scene.hpp"

namespace fs = std::filesystem;

namespace {

int files_in(const fs::path& dir) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file() ? 1 : 0;
    return n;
}

std::vector<std::uint8_t> pixels_of(const fs::path& path) {
    kerf::render::PngPicture p;
    const std::string why = kerf::render::read_png(path.string(), p);
    INFO(path << ": " << why);
    REQUIRE(why.empty());
    return p.pixels;
}

}  // namespace

TEST_CASE("farm options that contradict or cannot be met are exit 2 and write nothing") {
    auto dir = test_dir("farm_options");
    write_file(dir / "scene.sdl", kFarmScene);
    const struct {
        const char* args;
        const char* error;
    } cases[] = {
        {"--frames 0", "--frames expects a whole number from 1 to 1000000, got '0'"},
        {"--frames x", "--frames expects a whole number from 1 to 1000000, got 'x'"},
        {"--tile 0/0", "--tile N expects a whole number from 1 to 32768, got '0'"},
        {"--tile 4/4", "--tile 4/4: K counts from 0, so it must be less than N = 4"},
        {"--tile 7/4", "--tile 7/4: K counts from 0, so it must be less than N = 4"},
        {"--tile 2", "--tile expects K/N (band K of N, K from 0), got '2'"},
        {"--tile -1/4", "--tile K expects a whole number from 0 to 32768, got '-1'"},
        {"--tile 0/50 -H 40", "--tile 0/50: 50 bands do not fit in 40 rows"},
        {"--frame 2", "--frame I needs --frames N, the animation's length ($t = (I-1)/N)"},
        {"--frames 4 --frame 5", "--frame 5 lies beyond --frames 4"},
        {"--frames 4 --tile 0/2", "--tile splits one image: tile one frame with -D '$t=...' instead of --frames"},
        {"--frames 4 -D '$t=0.5'", "--frames sets $t for each frame; drop -D '$t=...'"},
        {"--tile 0/2 --crop 0,0,8,8", "--tile renders a band of the whole image; drop --crop"},
        {"--tile 0/2 --aov depth", "--tile joins colour renders; --aov images are normalised over the whole picture"},
        {"--resume", "--resume applies to --frames and --tile"},
        {"--frames 2 -o -", "--frames writes numbered files; -o - names none"},
    };
    for (const auto& c : cases) {
        const auto r = run_kerf("render " + quoted(dir, "scene.sdl") + " " + c.args, dir);
        INFO(c.args);
        CHECK(r.status == 2);
        CHECK(first_line(r.err) == std::string("kerf: error: ") + c.error);
    }
    const std::string out = (dir / "out.jpg").string();
    auto r = run_kerf("render " + quoted(dir, "scene.sdl") + " --tile 0/2 -o '" + out + "'", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: --tile needs PNG output (the metadata that joins and checks the "
                               "files is a PNG text chunk), got -o " + out);
    // check and dump take render options and ignore them (docs/spec.md §7),
    // their values still checked.
    r = run_kerf("check " + quoted(dir, "scene.sdl") + " --frames 3 --tile 0/2", dir);
    CHECK(r.status == 0);
    r = run_kerf("check " + quoted(dir, "scene.sdl") + " --tile 2/2", dir);
    CHECK(r.status == 2);
    for (const char* args : {"assemble", "assemble out.png", "assemble out.png --frames"}) {
        r = run_kerf(args, dir);
        INFO(args);
        CHECK(r.status == 2);
    }
    CHECK(files_in(dir) == 3);  // scene.sdl and the captured stdout and stderr
}

TEST_CASE("an unwritable frame name is exit 3 before any frame is rendered, nothing overwritten") {
    auto dir = test_dir("farm_unwritable");
    write_file(dir / "scene.sdl", kFarmScene);
    auto r = run_kerf("render " + quoted(dir, "scene.sdl") + " --frames 3 -W 32 -H 24 -o /nonexistent/a.png", dir);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write /nonexistent/a_0001.png: no folder '/nonexistent'\n");
    // Frame 1 exists from before, frame 3's name is taken by a folder: the
    // run stops at the check, frame 1 keeps its bytes and 2 is not written.
    write_file(dir / "a_0001.png", "old");
    fs::create_directories(dir / "a_0003.png");
    r = run_kerf("render " + quoted(dir, "scene.sdl") + " --frames 3 -W 32 -H 24 -o " + quoted(dir, "a.png"), dir);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write " + (dir / "a_0003.png").string() + ": it is a folder\n");
    CHECK(slurp(dir / "a_0001.png") == "old");
    CHECK_FALSE(fs::exists(dir / "a_0002.png"));
    r = run_kerf("render " + quoted(dir, "scene.sdl") + " --tile 1/2 -W 32 -H 24 -o /nonexistent/t.png", dir);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write /nonexistent/t_tile1of2.png: no folder '/nonexistent'\n");
}

TEST_CASE("frames are named OUT_0001 .. OUT_N and frame I is the scene at $t = (I-1)/N") {
    auto dir = test_dir("farm_frames");
    write_file(dir / "scene.sdl", kFarmScene);
    render_farm_scene(dir, "--frames 4 -W 40 -H 30 -o " + quoted(dir, "a.png"));
    for (const char* f : {"a_0001.png", "a_0002.png", "a_0003.png", "a_0004.png"}) CHECK(fs::exists(dir / f));
    CHECK_FALSE(fs::exists(dir / "a_0000.png"));
    CHECK_FALSE(fs::exists(dir / "a_0005.png"));
    // The oracle: a plain render with $t set by hand.
    for (const auto& [frame, t] : {std::pair{"a_0001.png", "0"}, std::pair{"a_0003.png", "0.5"}}) {
        render_farm_scene(dir, "-W 40 -H 30 -D '$t=" + std::string(t) + "' -o " + quoted(dir, "plain.png"));
        INFO(frame);
        CHECK(pixels_of(dir / frame) == pixels_of(dir / "plain.png"));
    }
    CHECK(pixels_of(dir / "a_0002.png") != pixels_of(dir / "a_0001.png"));  // the scene does move
    // --frame I renders only frame I; the number grows past 4 digits.
    render_farm_scene(dir, "--frames 12000 --frame 11999 -W 40 -H 30 -o " + quoted(dir, "b.png"));
    CHECK(fs::exists(dir / "b_11999.png"));
    CHECK_FALSE(fs::exists(dir / "b_12000.png"));
    render_farm_scene(dir, "--frames 7 --frame 3 -W 40 -H 30 -o " + quoted(dir, "c.png"));
    CHECK(fs::exists(dir / "c_0003.png"));
    CHECK(fs::exists(dir / "c_0002.png") == false);
}

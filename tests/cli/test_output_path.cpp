// `kerf render -o OUT` (docs/spec.md §7–§8): an output that cannot be written is
// exit 3 with one line, decided before the scene is evaluated; an existing
// image is never destroyed by a render that fails or is killed.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

namespace fs = std::filesystem;

namespace {

// Evaluating this would be exit 1: getting exit 3 instead proves the output
// was checked first, without timing anything.
const std::string kBrokenScene = "sphere(1)\n";

int regular_files_in(const fs::path& dir) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file() ? 1 : 0;
    return n;
}

}  // namespace

TEST_CASE("an output format OpenImageIO cannot write is exit 3 before evaluation") {
    auto dir = test_dir("out_format");
    const auto scene = write_file(dir / "broken.sdl", kBrokenScene);
    for (const std::string name : {"out.xyz", "out.sdl"}) {
        const auto out = (dir / name).string();
        const KerfRun r = run_kerf("render '" + scene + "' -o '" + out + "'", dir);
        CHECK(r.status == 3);
        const auto ext = fs::path(name).extension().string();
        CHECK(r.err == "kerf: error: cannot write " + out + ": OpenImageIO cannot write '" + ext + "' files\n");
    }
    const auto bare = (dir / "out").string();
    const KerfRun r = run_kerf("render '" + scene + "' -o '" + bare + "'", dir);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write " + bare + ": no extension to choose the image format by\n");
}

TEST_CASE("an output in a missing folder, or that is a folder, is exit 3 before evaluation") {
    auto dir = test_dir("out_folder");
    const auto scene = write_file(dir / "broken.sdl", kBrokenScene);
    KerfRun r = run_kerf("render '" + scene + "' -o /nonexistent/dir/out.png", dir);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write /nonexistent/dir/out.png: no folder '/nonexistent/dir'\n");

    // A file where a folder should be.
    const auto under_file = scene + "/out.png";
    r = run_kerf("render '" + scene + "' -o '" + under_file + "'", dir);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write " + under_file + ": no folder '" + scene + "'\n");

    fs::create_directories(dir / "taken.png");
    const auto folder = (dir / "taken.png").string();
    r = run_kerf("render '" + scene + "' -o '" + folder + "'", dir);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write " + folder + ": it is a folder\n");
    CHECK(fs::is_directory(folder));
}

TEST_CASE("the output check leaves no file behind, and a good output renders") {
    auto dir = test_dir("out_ok");
    const auto scene = write_file(dir / "ok.sdl", "sphere(1);\n");
    const auto out = dir / "ok.exr";
    const KerfRun r = run_kerf("render '" + scene + "' -W 8 -H 8 -o '" + out.string() + "'", dir);
    CHECK(r.status == 0);
    CHECK(fs::file_size(out) > 0);
    // The scene, the image, and the captured stdout/stderr: no probe file.
    CHECK(regular_files_in(dir) == 4);
}

TEST_CASE("an existing image survives a failed or killed render") {
    auto dir = test_dir("out_keep");
    const auto out = dir / "keep.png";
    const auto good = write_file(dir / "good.sdl", "sphere(1);\n");
    REQUIRE(run_kerf("render '" + good + "' -W 8 -H 8 -o '" + out.string() + "'", dir).status == 0);
    const std::string before = slurp(out);
    REQUIRE(!before.empty());
    const int files = regular_files_in(dir);

    // A scene error.
    const auto broken = write_file(dir / "broken.sdl", kBrokenScene);
    CHECK(run_kerf("render '" + broken + "' -W 8 -H 8 -o '" + out.string() + "'", dir).status == 1);
    CHECK(slurp(out) == before);

    // Killed mid-render: 4000x4000 at 64 spp is ~10^9 rays, minutes of work,
    // so the 2 s timeout always interrupts it before the image is written.
    const KerfRun killed =
        run_kerf("render '" + good + "' -W 4000 -H 4000 --spp 64 -o '" + out.string() + "'", dir, "exec timeout 2 ");
    CHECK(killed.status == 124);
    CHECK(slurp(out) == before);
    CHECK(regular_files_in(dir) == files + 1);  // + broken.sdl, no temporary

    // The same output is replaced by a render that succeeds (so the checks
    // above can fail).
    REQUIRE(run_kerf("render '" + good + "' -W 9 -H 8 -o '" + out.string() + "'", dir).status == 0);
    CHECK(slurp(out) != before);
}

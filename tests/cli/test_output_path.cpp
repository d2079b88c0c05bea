// `kerf render -o OUT` (docs/spec.md §7–§8): an output that cannot be written is
// exit 3 with one line, decided before the scene is evaluated; an existing
// image is never destroyed by a render that fails or is killed.
#include <catch2/catch.hpp>

#include <csignal>
#include <set>

#include "tests/cli/run_kerf.hpp"
#include "tests/cli/spawn_kerf.hpp"

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

TEST_CASE("a signal while the image is being written leaves the old image and no temporary", "[output]") {
    // kerf is stopped (SIGSTOP) once it holds a temporary with bytes in it,
    // not yet renamed, then sent the signal: it must end by that signal with
    // the old image intact and nothing else in the folder. Before, a named
    // temporary ".keep.kerf-tmp-PID-N.bmp" stayed behind.
    auto dir = test_dir("out_signal");
    const auto scene = write_file(dir / "far.sdl", "translate([1000, 0, 0]) cube(0.01);\n");  // cheap pixels
    const auto out = dir / "keep.bmp";
    REQUIRE(run_kerf("render '" + scene + "' -W 8 -H 8 -o '" + out.string() + "'", dir).status == 0);
    const std::string before = slurp(out);
    const auto names = [&] {
        std::set<std::string> n;
        for (const auto& e : fs::directory_iterator(dir)) n.insert(e.path().filename().string());
        return n;
    };
    const std::set<std::string> expected = names();
    struct Case {
        int sig;
        bool without_tmpfile;  // the named temporary, as on file systems without O_TMPFILE
    };
    // SIGKILL runs no handler: only the anonymous temporary can promise it.
    for (const Case c : {Case{SIGTERM, false}, Case{SIGINT, false}, Case{SIGKILL, false}, Case{SIGTERM, true},
                         Case{SIGINT, true}}) {
        INFO("signal " << c.sig << (c.without_tmpfile ? ", named temporary" : ", O_TMPFILE"));
        bool caught = false;
        // A 3000x2000 BMP is 18 MB: tens of milliseconds of writing to
        // catch; a busy machine may still miss it, so up to three tries.
        for (int attempt = 0; attempt < 3 && !caught; ++attempt) {
            SpawnOptions options;
            options.without_tmpfile = c.without_tmpfile;
            const pid_t pid = spawn_kerf({"render", scene, "-W", "3000", "-H", "2000", "-o", out.string()}, options);
            REQUIRE(pid > 0);
            int status = -1;
            caught = stop_while_writing(pid, dir, status);
            if (!caught) {
                REQUIRE(status == 0);  // finished before it was caught: try again
                write_file(out, before);
                continue;
            }
            ::kill(pid, c.sig);
            ::kill(pid, SIGCONT);
            CHECK(wait_kerf(pid) == 128 + c.sig);
        }
        REQUIRE(caught);
        CHECK(slurp(out) == before);
        CHECK(names() == expected);
    }
}

TEST_CASE("the output is never the scene: by name, ./, a symlink or a hard link", "[output]") {
    auto dir = test_dir("out_is_input");
    // `kerf render model.png` would write model.png, over its own scene.
    const std::string text = "sphere(1);\n";
    const auto scene = write_file(dir / "model.png", text);
    fs::create_symlink(dir / "model.png", dir / "link.png");
    fs::create_hard_link(dir / "model.png", dir / "hard.png");
    const std::string same[] = {"", (dir / "." / "model.png").string(), (dir / "link.png").string(),
                                (dir / "hard.png").string()};
    for (const std::string& out : same) {
        INFO("-o '" << out << "'");
        const KerfRun r = run_kerf("render '" + scene + "' -W 8 -H 8" + (out.empty() ? "" : " -o '" + out + "'"), dir);
        CHECK(r.status == 3);
        CHECK(r.err == "kerf: error: cannot write " + (out.empty() ? scene : out) + ": it is the input file " +
                           scene + "\n");
        CHECK(slurp(scene) == text);
        CHECK(fs::is_symlink(dir / "link.png"));
    }
    // A different file of the same content is not the scene.
    const auto copy = dir / "copy.png";
    fs::copy_file(scene, copy);
    CHECK(run_kerf("render '" + scene + "' -W 8 -H 8 -o '" + copy.string() + "'", dir).status == 0);
    CHECK(slurp(copy) != text);
}

TEST_CASE("an empty -o name is a usage error, not the default", "[output]") {
    auto dir = test_dir("out_empty");
    const auto scene = write_file(dir / "s.sdl", "sphere(1);\n");
    const KerfRun r = run_kerf("render '" + scene + "' -W 8 -H 8 -o ''", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: -o needs a file name, got ''");
    CHECK_FALSE(fs::exists(dir / "s.png"));  // not quietly the default either
}

TEST_CASE("an output name of 250 bytes is written: the temporary's name is short", "[output]") {
    auto dir = test_dir("out_long_name");
    const auto scene = write_file(dir / "s.sdl", "sphere(1);\n");
    for (const std::string ext : {".png", ".exr"}) {
        const auto out = dir / (std::string(250 - ext.size(), 'n') + ext);
        REQUIRE(out.filename().string().size() == 250);
        const KerfRun r = run_kerf("render '" + scene + "' -W 8 -H 8 -o '" + out.string() + "'", dir);
        CHECK(r.status == 0);
        CHECK(r.err.empty());
        CHECK(fs::file_size(out) > 0);
    }
}

TEST_CASE("JPEG 2000 below 32 pixels is exit 3 before rendering, not a 77-byte file", "[output]") {
    // OpenJPEG's 6 resolution levels need 32 pixels each way; its writer
    // reported success over a file that reads back as nothing.
    auto dir = test_dir("out_small_jp2");
    const auto scene = write_file(dir / "broken.sdl", kBrokenScene);  // checked first: exit 3, not 1
    const auto out = dir / "small.jp2";
    KerfRun r = run_kerf("render '" + scene + "' -W 31 -H 64 -o '" + out.string() + "'", dir);
    CHECK(r.status == 3);
    CHECK(r.err == "kerf: error: cannot write " + out.string() +
                       ": JPEG 2000 needs at least 32x32 pixels (OpenJPEG's 6 resolution levels), "
                       "the image is 31x64\n");
    // The image written is the crop.
    r = run_kerf("render '" + scene + "' -W 64 -H 64 --crop 0,0,40,20 -o '" + out.string() + "'", dir);
    CHECK(r.status == 3);
    CHECK(r.err.find("the image is 40x20") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
    const auto good = write_file(dir / "good.sdl", "sphere(1);\n");
    CHECK(run_kerf("render '" + good + "' -W 32 -H 32 -o '" + out.string() + "'", dir).status == 0);
    CHECK(fs::file_size(out) > 77);
}

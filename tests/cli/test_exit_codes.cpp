// docs/spec.md §8 exit statuses and the one-line diagnostics, through the real binary.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

namespace fs = std::filesystem;

TEST_CASE("kerf without arguments or with a bad option exits 2 with a usage error") {
    auto dir = test_dir("usage");
    auto r = run_kerf("", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: no command given (try 'kerf --help')");

    r = run_kerf("render x.sdl --frobnicate", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: unknown option '--frobnicate'");

    r = run_kerf("render x.sdl -W 0", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: -W expects a whole number from 1 to 32768, got '0'");

    r = run_kerf("render x.sdl --aov colour", dir);
    CHECK(r.status == 2);

    r = run_kerf("render x.sdl -W 10 -H 10 --crop 0,0,20,5", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: --crop rectangle lies outside the 10x10 image");
}

TEST_CASE("kerf --help prints usage and exits 0") {
    auto dir = test_dir("help");
    auto r = run_kerf("--help", dir);
    CHECK(r.status == 0);
    CHECK(r.out.find("kerf render SCENE.sdl") != std::string::npos);
}

TEST_CASE("an unreadable scene file exits 2") {
    auto dir = test_dir("missing");
    auto r = run_kerf("check '" + (dir / "nope.sdl").string() + "'", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err).rfind("kerf: error: cannot open '" + (dir / "nope.sdl").string() + "'", 0) == 0);

    r = run_kerf("check '" + dir.string() + "'", dir);  // a directory
    CHECK(r.status == 2);
}

TEST_CASE("a scene with a syntax error exits 1 with a located diagnostic and caret") {
    auto dir = test_dir("syntax");
    auto path = write_file(dir / "bad.sdl", "cube(1);\nsphere(2)\n");
    auto r = run_kerf("check '" + path + "'", dir);
    CHECK(r.status == 1);
    CHECK(first_line(r.err) == path + ":2:10: error: expected ';'");  // where the statement ends
}

TEST_CASE("an evaluation error exits 1 naming the statement") {
    auto dir = test_dir("eval");
    auto path = write_file(dir / "bad.sdl", "r = sqrt(-1);\nsphere(r);\n");
    auto r = run_kerf("check '" + path + "'", dir);
    CHECK(r.status == 1);
    CHECK(first_line(r.err).rfind(path + ":2:1: error: ", 0) == 0);
}

TEST_CASE("check and dump succeed on a valid scene") {
    auto dir = test_dir("valid");
    auto path = write_file(dir / "ok.sdl", "difference() { cube(2, center = true); sphere(1.2); }\n");
    auto r = run_kerf("check '" + path + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    r = run_kerf("dump '" + path + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.out.find("difference") != std::string::npos);
}

TEST_CASE("render writes the image, and exits 3 when it cannot") {
    auto dir = test_dir("render");
    auto path = write_file(dir / "ok.sdl", "sphere(1);\n");
    auto out = dir / "ok.png";
    auto r = run_kerf("render '" + path + "' -W 32 -H 24 -o '" + out.string() + "'", dir);
    CHECK(r.status == 0);
    CHECK(fs::exists(out));
    CHECK(fs::file_size(out) > 0);

    // Default output: SCENE.png beside the scene.
    r = run_kerf("render '" + path + "' -W 8 -H 8", dir);
    CHECK(r.status == 0);
    CHECK(fs::exists(dir / "ok.png"));

    r = run_kerf("render '" + path + "' -W 8 -H 8 -o '" + (dir / "no/such/dir/x.png").string() + "'", dir);
    CHECK(r.status == 3);
    CHECK(first_line(r.err).rfind("kerf: error: ", 0) == 0);
}

TEST_CASE("defines (-D) on the command line override a top-level binding") {
    auto dir = test_dir("define");
    auto path = write_file(dir / "d.sdl", "n = 1;\nassert(n == 3, \"n is not 3\");\ncube(n);\n");
    CHECK(run_kerf("check '" + path + "'", dir).status == 1);
    CHECK(run_kerf("check '" + path + "' -D n=3", dir).status == 0);
    CHECK(run_kerf("check '" + path + "' -D 'n=1+2'", dir).status == 0);
}

TEST_CASE("a scene file that never ends (/dev/zero) exits 2 instead of reading forever") {
    auto dir = test_dir("endless");
    auto r = run_kerf("check /dev/zero", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: cannot read '/dev/zero': longer than 256 MiB, too large for a scene script");
}

// --werror (docs/spec.md §11 "Warnings"): every warning is reported, located,
// as an error and the run fails with the scene-error status, after the
// whole script has run; without it the same file passes with warnings.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

TEST_CASE("werror: turns each located warning into an error and exits 1") {
    auto dir = test_dir("werror");
    const std::string scad = write_file(dir / "warned.scad", "a = 1;\na = 2;\necho(a);\ncube(a);\n");
    const std::string warned = scad + ":2:1: warning: a was assigned on line 1 but was overwritten";
    const std::string errored = scad + ":2:1: error: a was assigned on line 1 but was overwritten [--werror]";

    auto r = run_kerf("check '" + scad + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find(warned) != std::string::npos);

    for (const char* cmd : {"check", "dump", "render -W 8 -H 8 --no-progress"}) {
        r = run_kerf(std::string(cmd) + " --werror '" + scad + "'", dir);
        CHECK(r.status == 1);
        CHECK(r.err.find("ECHO: 2") != std::string::npos);  // the script ran to its end
        CHECK(r.err.find(errored) != std::string::npos);
        CHECK(r.err.find(warned) == std::string::npos);
        CHECK(r.out.empty());
    }
    CHECK_FALSE(std::filesystem::exists(dir / "warned.png"));
}

TEST_CASE("werror: keeps warnings and errors of one run in their order, and is silent on a clean file") {
    auto dir = test_dir("werror_mixed");
    const std::string scad = write_file(dir / "mixed.scad", "a = 1;\na = 2;\nassert(false);\n");
    auto r = run_kerf("check --werror '" + scad + "'", dir);
    CHECK(r.status == 1);
    const auto warn_at = r.err.find(scad + ":2:1: error: a was assigned");
    const auto error_at = r.err.find(scad + ":3:1: error: assertion failed");
    CHECK(warn_at != std::string::npos);
    CHECK(error_at != std::string::npos);
    CHECK(warn_at < error_at);

    const std::string clean = write_file(dir / "clean.scad", "cube(1);\n");
    r = run_kerf("check --werror '" + clean + "'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
}

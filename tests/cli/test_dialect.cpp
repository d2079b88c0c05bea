// The dialect of a run (docs/openscad.md): chosen by the main file's
// extension, overridden by --strict, --lenient or --openscad.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

TEST_CASE("a .scad file is lenient, a .sdl file strict, and the flags override either way") {
    auto dir = test_dir("dialect");
    const std::string text = "a = 1;\na = 2;\necho(a);\n";
    const std::string scad = write_file(dir / "twice.scad", text);
    const std::string sdl = write_file(dir / "twice.sdl", text);
    const std::string warned = scad + ":2:1: warning: a was assigned on line 1 but was overwritten";

    auto r = run_kerf("check '" + scad + "'", dir);
    CHECK(r.status == 0);
    CHECK(first_line(r.err) == "ECHO: 2");
    CHECK(r.err.find(warned) != std::string::npos);

    r = run_kerf("check '" + sdl + "'", dir);
    CHECK(r.status == 1);
    CHECK(first_line(r.err) == sdl + ":2:1: error: 'a' is already defined at line 1");

    r = run_kerf("check --strict '" + scad + "'", dir);
    CHECK(r.status == 1);
    CHECK(first_line(r.err) == scad + ":2:1: error: 'a' is already defined at line 1");

    for (const char* flag : {"--lenient", "--openscad"}) {
        r = run_kerf(std::string("check ") + flag + " '" + sdl + "'", dir);
        CHECK(r.status == 0);
        CHECK(first_line(r.err) == "ECHO: 2");
    }
}

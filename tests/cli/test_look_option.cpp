// --look studio|plain (docs/language.md, "The default look"): a bad value is
// a usage error, measure refuses it (it writes no image), and dump shows the
// look's set-up: the studio ground as a scene line, never in the tree.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

TEST_CASE("the look option: bad values and measure are usage errors, dump shows each look") {
    auto dir = test_dir("look_option");
    write_file(dir / "s.scad", "translate([0, 0, 2]) cube([10, 6, 1]);\n");
    const std::string s = "'" + (dir / "s.scad").string() + "'";
    auto r = run_kerf("render " + s + " --look glossy", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: --look expects studio or plain, got 'glossy'");
    r = run_kerf("measure " + s + " --look plain", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: measure writes no image; --look does not apply to it");
    r = run_kerf("dump " + s, dir);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\nground z=2 shadow=0.6\n") != std::string::npos);
    CHECK(r.out.find("background color=[0.5 0.5 0.5]") != std::string::npos);
    CHECK(r.out.find("scene leaves=1 nodes=1 ") != std::string::npos);  // one cube, no ground leaf
    r = run_kerf("dump " + s + " --look plain", dir);
    REQUIRE(r.status == 0);
    CHECK(r.out.find("\nground ") == std::string::npos);
    CHECK(r.out.find("background color=[0.2 0.2 0.2]") != std::string::npos);
    CHECK(r.out.find("scene leaves=1 nodes=1 ") != std::string::npos);
}

// intersection_for: the intersection of its passes, each pass the union of
// what it makes (as OpenSCAD), checked point by point against the same
// solid written out with intersection() (csg::contains, no ray code).
#include <catch2/catch.hpp>

#include <random>

#include "csg/membership.hpp"
#include "tests/lower/script_scene.hpp"

using namespace kerf;

TEST_CASE("intersection_for is the intersection of its passes") {
    // OpenSCAD's examples/Old/example014.scad, at a tenth of its size, and
    // two loop variables with a two-solid body.
    const struct {
        const char* loop;
        const char* written;
    } cases[] = {
        {"intersection_for(i = [[0, 0, 0], [10, 20, 300], [200, 40, 57], [20, 88, 57]])"
         " rotate(i) cube([10, 2, 2], center = true);",
         "intersection() { rotate([0, 0, 0]) cube([10, 2, 2], center = true);"
         " rotate([10, 20, 300]) cube([10, 2, 2], center = true);"
         " rotate([200, 40, 57]) cube([10, 2, 2], center = true);"
         " rotate([20, 88, 57]) cube([10, 2, 2], center = true); }"},
        {"intersection_for(x = [-0.5, 0.5], y = [0, 0.7]) { translate([x, y, 0]) sphere(2); translate([x, 0, 3]) cube(1); }",
         "intersection() {"
         " union() { translate([-0.5, 0, 0]) sphere(2); translate([-0.5, 0, 3]) cube(1); }"
         " union() { translate([-0.5, 0.7, 0]) sphere(2); translate([-0.5, 0, 3]) cube(1); }"
         " union() { translate([0.5, 0, 0]) sphere(2); translate([0.5, 0, 3]) cube(1); }"
         " union() { translate([0.5, 0.7, 0]) sphere(2); translate([0.5, 0, 3]) cube(1); } }"},
    };
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> u(-4, 4);
    for (const auto& c : cases) {
        INFO(c.loop);
        const csg::Scene a = test::lowered(c.loop), b = test::lowered(c.written);
        int inside = 0;
        for (int i = 0; i < 20000; ++i) {
            const glm::dvec3 p(u(rng), u(rng), u(rng));
            const bool in = csg::contains(b, p);
            inside += in;
            REQUIRE(csg::contains(a, p) == in);
        }
        CHECK(inside > 20);  // the intersection is not empty
    }
    // One pass is that pass; no pass is nothing.
    CHECK(test::lowered("intersection_for(i = [1]) sphere(i);").leaves.size() == 1);
    CHECK(test::lowered("intersection_for(i = []) sphere(1);").leaves.empty());
}

// The `%` and `#` modifiers' ghosts (csg/ghosts.hpp): which subtree each
// kind's tree holds, under which transform and colour, and where OpenSCAD's
// preview shows none. The solid's side is in test_modules.cpp.
#include <catch2/catch.hpp>

#include "csg/ghosts.hpp"
#include "tests/interpreter/eval_helpers.hpp"

using kerf::csg::GhostKind;
using kerf::test::run;
using kerf::test::shape;

namespace {

// The shape of one kind's ghost tree ("none" without one).
std::string ghost_shape(const std::string& text, GhostKind kind) {
    const auto g = run(text).graph;
    const std::uint32_t root = g.ghost_roots[std::size_t(kind)];
    return root == kerf::csg::kNone ? "none" : shape(g, root);
}

std::vector<kerf::test::Leaf> ghost_leaves(const kerf::graph::SceneGraph& g, GhostKind kind) {
    std::vector<kerf::test::Leaf> out;
    const std::uint32_t root = g.ghost_roots[std::size_t(kind)];
    if (root != kerf::csg::kNone) kerf::test::collect(g, root, glm::dmat4(1.0), nullptr, out);
    return out;
}

}  // namespace

TEST_CASE("a % part is a background ghost, not in the solid", "[ghosts]") {
    const char* text = "%cube();\nsphere();";
    CHECK(kerf::test::shape_of(text) == "U(sphere)");
    CHECK(ghost_shape(text, GhostKind::Background) == "U(A(T(box)))");
    CHECK(ghost_shape(text, GhostKind::Highlight) == "none");
    const auto g = run(text).graph;
    const auto ghosts = ghost_leaves(g, GhostKind::Background);
    REQUIRE(ghosts.size() == 1);
    // OpenSCAD's grey at alpha 128/255.
    CHECK(ghosts[0].material.color.x == Approx(kerf::csg::srgb_to_linear(180.0 / 255)));
    CHECK(ghosts[0].material.transparency == Approx(127.0 / 255));
}

TEST_CASE("a # part stays in the solid and is a highlight ghost too", "[ghosts]") {
    const char* text = "#cube();\nsphere();";
    CHECK(kerf::test::shape_of(text) == "U(box,sphere)");
    CHECK(ghost_shape(text, GhostKind::Highlight) == "U(T(box))");
    CHECK(ghost_shape(text, GhostKind::Background) == "none");
    // A subtrahend: still cut from the solid, its whole self the ghost.
    const char* hole = "difference() { cube(10, center = true); #cylinder(r = 3, h = 14, center = true); }";
    CHECK(kerf::test::shape_of(hole) == "U(D(box,cylinder))");
    CHECK(ghost_shape(hole, GhostKind::Highlight) == "U(T(cylinder))");
    // A minuend: OpenSCAD highlights the difference made of it.
    CHECK(ghost_shape("difference() { #cube(); sphere(); }", GhostKind::Highlight) == "U(T(D(box,sphere)))");
    // % inside a difference: not subtracted (the next child is the minuend, as OpenSCAD's), a ghost.
    CHECK(kerf::test::shape_of("difference() { cube(); %sphere(); }") == "U(D(box))");
    CHECK(ghost_shape("difference() { cube(); %sphere(); }", GhostKind::Background) == "U(A(T(sphere)))");
}

TEST_CASE("a ghost is placed by the transforms around its statement", "[ghosts]") {
    const auto g = run("module m() translate([0, 5, 0]) children();\n"
                       "translate([1, 2, 3]) rotate([0, 0, 90]) m() %cube();").graph;
    const auto ghosts = ghost_leaves(g, GhostKind::Background);
    REQUIRE(ghosts.size() == 1);
    const glm::dvec4 origin = ghosts[0].world * glm::dvec4(0, 0, 0, 1);
    CHECK(origin.x == Approx(1 - 5));
    CHECK(origin.y == Approx(2));
    CHECK(origin.z == Approx(3));
    // A 2D part: the plane part of the transforms, then the plate 1 thick on z = 0.
    const auto flat = ghost_leaves(run("translate([1, 0, 7]) %square(2);").graph, GhostKind::Background);
    REQUIRE(flat.size() == 1);
    const glm::dvec4 corner = flat[0].world * glm::dvec4(0, 0, 0, 1);
    CHECK(corner.x == Approx(1));
    CHECK(corner.z == Approx(-0.5));
}

TEST_CASE("a % ghost keeps the colour around it, a # ghost does not", "[ghosts]") {
    const auto g = run("color([1, 0, 0]) %cube();\n#color([0, 0, 1]) sphere();").graph;
    const auto background = ghost_leaves(g, GhostKind::Background);
    REQUIRE(background.size() == 1);
    CHECK(background[0].material.color == glm::dvec3(1, 0, 0));
    CHECK(background[0].material.transparency == 0);  // OpenSCAD draws it opaque: the colour's alpha
    // The highlight pink is lowering's (every material of the # tree); the graph keeps the user's.
    CHECK(ghost_shape("#color([0, 0, 1]) sphere();", GhostKind::Highlight) == "U(T(A(sphere)))");
}

TEST_CASE("ghosts with ! and *, and where OpenSCAD's preview shows none", "[ghosts]") {
    // Only the ghosts inside the statement that became the root.
    const char* text = "%cylinder();\n!translate([1, 0, 0]) { cube(); %sphere(); }";
    CHECK(kerf::test::shape_of(text) == "U(T(box))");
    CHECK(ghost_shape(text, GhostKind::Background) == "U(A(T(sphere)))");
    CHECK(ghost_shape("*%cube();\n*#cube();", GhostKind::Background) == "none");
    CHECK(ghost_shape("*%cube();\n*#cube();", GhostKind::Highlight) == "none");
    // Under an operation that rebuilds its children: none, with a warning.
    const auto r = run("rotate_extrude() { translate([3, 0]) circle(1); %translate([6, 0]) circle(1); }\n"
                       "linear_extrude(2) #square(1);");
    CHECK(r.graph.ghost_roots[0] == kerf::csg::kNone);
    CHECK(r.graph.ghost_roots[1] == kerf::csg::kNone);
    REQUIRE(r.warnings.size() == 2);
    CHECK(r.warnings[0].message == "'%' inside rotate_extrude() shows no ghost, as in OpenSCAD's preview");
    CHECK(r.warnings[1].message ==
          "'#' inside linear_extrude() shows no ghost, as in OpenSCAD's preview (the part is in the solid)");
    // Flattened by its transforms: no ghost, with a warning.
    const auto flat = run("multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0]]) %cube();");
    CHECK(flat.graph.ghost_roots[0] == kerf::csg::kNone);
    REQUIRE_FALSE(flat.warnings.empty());
    CHECK(flat.warnings[0].message == "'%': the transforms around this part flatten it: no ghost is shown");
}

// Statement forms beyond the basics: echo/assert with children, render and
// group, $-loop variables, scene statements from an included file.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "tests/interpreter/eval_helpers.hpp"

using kerf::test::echoes;
using kerf::test::error_of;
using kerf::test::shape_of;

TEST_CASE("echo and assert statements pass their children through", "[statements]") {
    CHECK(shape_of("echo(\"x\") cube();") == "U(box)");
    CHECK(shape_of("assert(true) { cube(); sphere(); }") == "U(U(box,sphere))");
    CHECK(error_of("assert(false) nosuch();") == "test.sdl:1:1: error: assertion failed");
    CHECK(error_of("assert(1, \"a\", 3);") == "test.sdl:1:16: error: too many arguments for 'assert' (takes 2)");
}

TEST_CASE("render and group are plain unions", "[statements]") {
    CHECK(shape_of("render(convexity = 2) { cube(); sphere(); }") == "U(U(box,sphere))");
    CHECK(shape_of("group() cube();") == "U(box)");
}

TEST_CASE("let statements bind for their block", "[statements]") {
    CHECK(echoes("let (a = 1, b = a + 1) { echo(a, b); }") == std::vector<std::string>{"ECHO: 1, 2"});
    CHECK(error_of("let (a = 1) cube(a);\necho(a);") == "test.sdl:2:6: error: undefined name 'a'");
    CHECK(echoes("module show() echo($r);\nlet ($r = 4) show();") == std::vector<std::string>{"ECHO: 4"});
}

TEST_CASE("$ loop variables are visible to called modules", "[statements]") {
    CHECK(echoes("module show() echo($i);\nfor ($i = [1:2]) show();") == std::vector<std::string>{"ECHO: 1", "ECHO: 2"});
}

TEST_CASE("a module's own use and nested definitions", "[statements]") {
    CHECK(echoes("module outer() {\n  module inner(x) echo(x);\n  inner(5);\n}\nouter();") == std::vector<std::string>{"ECHO: 5"});
    CHECK(error_of("module outer() { module inner() {} }\ninner();") == "test.sdl:2:1: error: unknown module 'inner'");
}

TEST_CASE("scene statements from an included file are at top level", "[statements]") {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / "kerf_interp_scene_inc";
    fs::create_directories(dir);
    std::ofstream(dir / "setup.sdl") << "camera(position = [5, 5, 5]);\nbackground(\"black\");\n";
    std::ofstream(dir / "main.sdl") << "include <setup.sdl>\nsphere();\n";
    auto r = kerf::evaluate_file((dir / "main.sdl").string());
    CHECK(r.graph.camera.has_value());
    CHECK(r.graph.background == glm::dvec3(0, 0, 0));
    fs::remove_all(dir);
}

TEST_CASE("a run reports at most 20 independent errors", "[statements]") {
    std::string text;
    for (int i = 0; i < 25; ++i) text += "cube(-1);\n";
    try {
        kerf::test::run(text);
        FAIL("no error");
    } catch (const kerf::SourceError& e) {
        REQUIRE(e.reported.size() == 20);
        CHECK(e.reported.back().loc.line == 20);
        CHECK(e.diagnostic().loc.line == 1);
    }
    // One error: nothing more to report, the diagnostic is all.
    try {
        kerf::test::run("cube(-1);");
        FAIL("no error");
    } catch (const kerf::SourceError& e) {
        CHECK(e.reported.size() == 1);
    }
}

// Evaluator::instantiate caches what a statement's name calls
// (ast::Stmt::dispatch): a control statement or a built-in module, found on
// the first pass. User modules are still looked up first on every pass.
TEST_CASE("a statement run many times calls what its name means on every pass", "[statements]") {
    // A user module named after a built-in wins on every pass of a loop.
    CHECK(shape_of("module cube(s) sphere(s);\nfor (i = [0:2]) cube(1);") == "U(U(sphere,sphere,sphere))");
    // The same module body run from a loop: its built-in call, every time.
    CHECK(shape_of("module m() cube();\nfor (i = [0:1]) m();") == "U(U(box,box))");
    // Control statements keep their meaning pass after pass.
    CHECK(echoes("module m(k) { for (j = [0:k]) echo(j); }\nfor (i = [0:1]) m(i);") ==
          std::vector<std::string>{"ECHO: 0", "ECHO: 0", "ECHO: 1"});
    CHECK(shape_of("for (i = [0:1]) intersection_for (j = [0:1]) { cube(); sphere(); }") ==
          "U(U(I(U(box,sphere),U(box,sphere)),I(U(box,sphere),U(box,sphere))))");
    CHECK(echoes("for (i = [0:1]) let (a = i * 2) echo(a);") == std::vector<std::string>{"ECHO: 0", "ECHO: 2"});
    CHECK(error_of("for (i = [0:1]) nosuch();") == "test.sdl:1:17: error: unknown module 'nosuch'");
}

// A call searches the scopes for a user module only once some block has
// defined one (eval_stmt.cpp): every place a definition can come from
// must set that, before the first call that needs it.
TEST_CASE("a built-in's name defined by a user module wherever it is defined", "[statements]") {
    // Inside another module's body, the only definition in the script.
    CHECK(shape_of("module m() { module translate(v) sphere(); translate([1, 0, 0]) cube(); }\nm();") == "U(sphere)");
    // The only definition in an if block, called before it in that block.
    CHECK(shape_of("if (true) { cube(); module cube() sphere(); }") == "U(sphere)");
    // The only definitions in a used file.
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "kerf_interp_use_override";
    fs::create_directories(dir);
    std::ofstream(dir / "lib.sdl") << "module cube(s) sphere(s);\n";
    std::ofstream(dir / "main.sdl") << "use <lib.sdl>\ncube(2);\n";
    auto r = kerf::evaluate_file((dir / "main.sdl").string());
    CHECK(kerf::test::shape(r.graph, r.graph.root) == "U(sphere)");
    fs::remove_all(dir);
}

// Built-in modules' arguments are matched into values held in the call's
// frame (modules/table.cpp, ArgValues): every parameter slot, the last of
// the module with the most parameters included.
TEST_CASE("a built-in module's arguments reach every parameter", "[statements]") {
    CHECK(shape_of("translate(v = [1, 2, 3]) cube(size = 2, center = true);") == "U(T(box))");
    CHECK(error_of("cube(1, true, 3);") == "test.sdl:1:15: error: too many arguments for 'cube' (takes 2)");
    CHECK(error_of("cube(size = 1, size = 2);") == "test.sdl:1:16: error: argument 'size' given twice to 'cube'");
    // material's 18th parameter, by name.
    CHECK(error_of("material(interpolation = 3) cube();") ==
          "test.sdl:1:1: error: material: interpolation must be \"bilinear\" or \"nearest\"");
}

// include/use (docs/spec.md §3): search order, what each imports, cycles; -D.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>

#include "tests/interpreter/eval_helpers.hpp"
#include "tests/interpreter/temp_tree.hpp"

namespace fs = std::filesystem;

namespace {

using kerf::test::TempTree;

std::vector<std::string> echo_file(const std::string& path, kerf::EvalOptions opt = {}) {
    std::vector<std::string> lines;
    opt.echo = [&](const std::string& l) { lines.push_back(l); };
    kerf::evaluate_file(path, opt);
    return lines;
}

std::string error_file(const std::string& path, kerf::EvalOptions opt = {}) {
    opt.echo = [](const std::string&) {};
    try {
        kerf::evaluate_file(path, opt);
    } catch (const kerf::SourceError& e) {
        return kerf::format_diagnostic_head(e.diagnostic());
    }
    return "no error";
}

}  // namespace

TEST_CASE("include inserts statements, use imports only definitions", "[include]") {
    TempTree t;
    t.write("lib.sdl", "k = 42;\nfunction twice(x) = 2 * x;\nmodule hello() echo(\"hello\", k);\necho(\"lib body\");\n");
    std::string inc = t.write("inc.sdl", "include <lib.sdl>\necho(k, twice(2));\nhello();\n");
    CHECK(echo_file(inc) == std::vector<std::string>{"ECHO: \"lib body\"", "ECHO: 42, 4", "ECHO: \"hello\", 42"});
    std::string use = t.write("use.sdl", "use <lib.sdl>\necho(twice(3));\nhello();\n");
    // The used file's own top-level variables are visible to its definitions.
    CHECK(echo_file(use) == std::vector<std::string>{"ECHO: 6", "ECHO: \"hello\", 42"});
    std::string use_var = t.write("use_var.sdl", "use <lib.sdl>\necho(k);\n");
    CHECK(error_file(use_var) == use_var + ":2:6: error: undefined name 'k'");
    // An included binding collides with one of the including file.
    std::string dup = t.write("dup.sdl", "k = 1;\ninclude <lib.sdl>\n");
    CHECK(error_file(dup) == t.path("lib.sdl") + ":1:1: error: 'k' is already defined at " + dup + ":1");
}

TEST_CASE("search order: file folder, then -I folders, then stdlib", "[include]") {
    TempTree t;
    t.write("main/near.sdl", "echo(\"near\");\n");
    t.write("inc1/near.sdl", "echo(\"inc1 near\");\n");
    t.write("inc1/only_inc.sdl", "echo(\"inc1\");\n");
    t.write("inc2/only_inc.sdl", "echo(\"inc2\");\n");
    t.write("std/only_std.sdl", "echo(\"std\");\n");
    t.write("inc2/only_std.sdl", "echo(\"inc2 std\");\n");
    t.write("std/sub/deep.sdl", "echo(\"deep\");\n");
    std::string main = t.write("main/main.sdl",
                               "include <near.sdl>\ninclude <only_inc.sdl>\ninclude <only_std.sdl>\ninclude <sub/deep.sdl>\n");
    kerf::EvalOptions opt;
    opt.include_dirs = {t.path("inc1"), t.path("inc2")};
    opt.stdlib_dir = t.path("std");
    CHECK(echo_file(main, opt) == std::vector<std::string>{"ECHO: \"near\"", "ECHO: \"inc1\"", "ECHO: \"inc2 std\"", "ECHO: \"deep\""});
    opt.include_dirs = {};
    CHECK(echo_file(t.write("main/m2.sdl", "include <only_std.sdl>\n"), opt) == std::vector<std::string>{"ECHO: \"std\""});
    std::string missing = t.write("main/missing.sdl", "\ninclude <nope.sdl>\n");
    CHECK(error_file(missing, opt) == missing + ":2:1: error: cannot find 'nope.sdl'");
    // Paths inside an included file resolve against that file's folder.
    t.write("main/a/b.sdl", "include <c.sdl>\n");
    t.write("main/a/c.sdl", "echo(\"a/c\");\n");
    CHECK(echo_file(t.write("main/nest.sdl", "include <a/b.sdl>\n"), opt) == std::vector<std::string>{"ECHO: \"a/c\""});
}

TEST_CASE("the stdlib shipped with kerf is found by default", "[include]") {
    TempTree t;
    std::string main = t.write("main.sdl", "use <shapes.sdl>\n");
    CHECK(error_file(main) == "no error");
}

TEST_CASE("include and use cycles are errors naming the chain", "[include]") {
    TempTree t;
    std::string a = t.write("a.sdl", "include <b.sdl>\n");
    std::string b = t.write("b.sdl", "x = 1;\ninclude <a.sdl>\n");
    CHECK(error_file(a) == b + ":2:1: error: include cycle: " + a + " -> " + b + " -> " + a);
    std::string self = t.write("self.sdl", "include <self.sdl>\n");
    CHECK(error_file(self) == self + ":1:1: error: include cycle: " + self + " -> " + self);
    std::string ua = t.write("ua.sdl", "use <ub.sdl>\n");
    std::string ub = t.write("ub.sdl", "use <ua.sdl>\n");
    // Mutual use is a cycle too (kerf is strict; OpenSCAD tolerates it).
    CHECK(error_file(ua) == ua + ":1:1: error: use cycle: " + ub + " -> " + ua + " -> " + ub);
    std::string uc = t.write("uc.sdl", "use <uc2.sdl>\n");
    std::string uc2 = t.write("uc2.sdl", "use <uc3.sdl>\n");
    std::string uc3 = t.write("uc3.sdl", "use <uc2.sdl>\n");
    CHECK(error_file(uc) == uc3 + ":1:1: error: use cycle: " + uc2 + " -> " + uc3 + " -> " + uc2);
}

TEST_CASE("defines (-D) override top-level bindings", "[include]") {
    kerf::EvalOptions opt;
    opt.defines = {{"size", "[1, 2] * 3"}, {"name", "\"kerf\""}};
    CHECK(kerf::test::echoes("size = 1;\nname = \"x\";\nhalf = size / 2;\necho(size, name, half);", opt) ==
          std::vector<std::string>{"ECHO: [3, 6], \"kerf\", [1.5, 3]"});
    kerf::EvalOptions bad;
    bad.defines = {{"size", "nosuch + 1"}};
    CHECK(kerf::test::error_of("size = 1;", bad) == "<command line>: error: -D size=nosuch + 1: undefined name 'nosuch'");
    bad.defines = {{"other", "1"}};
    CHECK(kerf::test::error_of("size = 1;", bad) == "<command line>: error: -D other: the script has no top-level binding 'other'");
    bad.defines = {{"size", "1 +"}};
    CHECK(kerf::test::error_of("size = 1;", bad).rfind("<command line>: error: -D size=1 +: ", 0) == 0);
    // A $ variable may be set without a binding in the script.
    kerf::EvalOptions dollar;
    dollar.defines = {{"$fn", "64"}};
    CHECK(kerf::test::echoes("module m() echo($fn);\nm();", dollar) == std::vector<std::string>{"ECHO: 64"});
    // Only top-level bindings are overridden.
    opt.defines = {{"v", "5"}};
    CHECK(kerf::test::echoes("v = 1;\nmodule m() { v = 2; echo(v); }\nm();\necho(v);", opt) ==
          std::vector<std::string>{"ECHO: 2", "ECHO: 5"});
}

// A file included twice is parsed once and its statements shared
// (ast::Stmt::dispatch caches what a name calls): the cache must hold the
// name's meaning, never the module it resolved to. x.sdl's cube() is the
// user's where main.sdl defines one, the built-in inside y.sdl.
TEST_CASE("a shared included statement resolves its module in each scope", "[include]") {
    TempTree t;
    t.write("x.sdl", "module m() cube();\n");
    t.write("y.sdl", "include <x.sdl>\nmodule n() m();\n");
    std::string main = t.write("main.sdl", "module cube() sphere();\ninclude <x.sdl>\nuse <y.sdl>\nm();\nn();\n");
    kerf::EvalOptions opt;
    opt.echo = [](const std::string&) {};
    auto g = kerf::evaluate_file(main, opt).graph;
    CHECK(kerf::test::shape(g, g.root) == "U(sphere,box)");
}

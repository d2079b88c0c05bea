// EvalOptions::on_dependency: every file a run reads or looked for, which
// `kerf watch` watches (docs/spec.md §13).
#include <catch2/catch.hpp>

#include <algorithm>

#include "interpreter/interpreter.hpp"
#include "tests/interpreter/temp_tree.hpp"

namespace {

using kerf::test::TempTree;

// The dependencies reported by evaluating `path` with -I `include_dir`
// and `stdlib` as the stdlib folder; the run must succeed or fail as `ok` says.
std::vector<std::string> dependencies(const std::string& path, const std::string& include_dir, const std::string& stdlib,
                                      bool ok) {
    std::vector<std::string> seen;
    kerf::EvalOptions opt;
    opt.echo = [](const std::string&) {};
    opt.include_dirs = {include_dir};
    opt.stdlib_dir = stdlib;
    opt.on_dependency = [&](const std::string& p) { seen.push_back(p); };
    if (ok) REQUIRE_NOTHROW(kerf::evaluate_file(path, opt));
    else REQUIRE_THROWS_AS(kerf::evaluate_file(path, opt), kerf::SourceError);
    return seen;
}

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

}  // namespace

TEST_CASE("a run reports its main file and every included, used and imported file", "[include]") {
    TempTree t;
    const std::pair<const char*, const char*> files[] = {
        {"std/.keep", ""},
        {"lib/used.sdl", "module m() sphere(1);\n"},
        {"main/part.sdl", "include <deeper.sdl>\n"},
        {"main/deeper.sdl", "cube(1);\n"},
        {"main/tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"},
    };
    for (const auto& [rel, text] : files) t.write(rel, text);
    const std::string main = t.write("main/scene.sdl", "include <part.sdl>\nuse <used.sdl>\nm();\nimport(\"tet.obj\");\n");
    const auto deps = dependencies(main, t.path("lib"), t.path("std"), true);
    CHECK(deps.front() == main);
    CHECK(has(deps, t.path("main/part.sdl")));
    CHECK(has(deps, t.path("main/deeper.sdl")));  // an include of an include
    CHECK(has(deps, t.path("lib/used.sdl")));
    // Found in -I, after the scene's own folder was searched: a used.sdl
    // created there would take its place, so that place is watched too.
    CHECK(has(deps, t.path("main/used.sdl")));
    CHECK(has(deps, t.path("main/tet.obj")));
    CHECK_FALSE(has(deps, t.path("lib/part.sdl")));  // found before -I was searched
}

TEST_CASE("a run that stops at a missing include still reports where it looked", "[include]") {
    TempTree t;
    t.write("std/.keep", "");
    const std::string main = t.write("main/scene.sdl", "include <later.sdl>\n");
    const auto deps = dependencies(main, t.path("lib"), t.path("std"), false);
    CHECK(has(deps, main));
    CHECK(has(deps, t.path("main/later.sdl")));
    CHECK(has(deps, t.path("lib/later.sdl")));
    CHECK(has(deps, t.path("std/later.sdl")));
}

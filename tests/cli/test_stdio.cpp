// Editors preview unsaved buffers: `kerf render -` reads the scene from
// standard input (includes resolve against --base DIR or the working
// folder) and `-o -` writes the PNG to standard output.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

namespace {

// kerf with the file `input` on standard input.
KerfRun run_piped(const std::filesystem::path& input, const std::string& args, const std::filesystem::path& dir) {
    return run_kerf(args, dir, "", input.string());
}

}  // namespace

TEST_CASE("a scene from standard input renders to standard output, as the same file does to a file") {
    auto dir = test_dir("stdio");
    std::filesystem::create_directories(dir / "lib");
    write_file(dir / "lib" / "parts.sdl", "module ball() sphere(1);\n");
    const std::string scene = "include <parts.sdl>\ncamera(position = [0, -5, 1], look_at = [0, 0, 0]);\nball();\n";
    write_file(dir / "lib" / "scene.sdl", scene);
    const auto in = dir / "in.sdl";
    write_file(in, scene);
    const std::string d = "'" + dir.string() + "/";
    const auto piped = run_piped(in, "render - -o - -W 40 -H 30 --base " + d + "lib'", dir);
    REQUIRE(piped.status == 0);
    const auto filed = run_kerf("render " + d + "lib/scene.sdl' -o " + d + "file.png' -W 40 -H 30", dir);
    REQUIRE(filed.status == 0);
    CHECK(piped.out.substr(1, 3) == "PNG");
    CHECK(piped.out == slurp(dir / "file.png"));
}

TEST_CASE("standard input and output: errors are located and clear") {
    auto dir = test_dir("stdio_errors");
    const auto bad = dir / "bad.sdl";
    write_file(bad, "sphere(1);\ncube(;\n");
    auto r = run_piped(bad, "check -", dir);
    CHECK(r.status == 1);
    CHECK(first_line(r.err).rfind("<stdin>:2:6: error: ", 0) == 0);
    // An include next to nothing: resolved against the working folder, so missing.
    const auto inc = dir / "inc.sdl";
    write_file(inc, "include <nowhere_to_be_found.sdl>\n");
    r = run_piped(inc, "check -", dir);
    CHECK(r.status != 0);
    CHECK(first_line(r.err).rfind("<stdin>:1:", 0) == 0);
    r = run_piped(bad, "render - -W 8 -H 8", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: a scene from standard input needs -o OUT (-o - writes the PNG to standard output)");
    r = run_kerf("render x.sdl --base /tmp", dir);
    CHECK(r.status == 2);
    CHECK(first_line(r.err) == "kerf: error: --base applies to a scene read from standard input ('-'), not to x.sdl");
    // A full standard output is a failed write, not a short image with exit 0.
    const auto ok = dir / "ok.sdl";
    write_file(ok, "sphere(1);\n");
    const int raw = std::system((std::string(KERF_BINARY_DIR) + "/kerf render - -o - -W 8 -H 8 <'" + ok.string() +
                                 "' >/dev/full 2>'" + (dir / "full.txt").string() + "'").c_str());
    CHECK(WEXITSTATUS(raw) == 3);
    CHECK(first_line(slurp(dir / "full.txt")) == "kerf: error: cannot write -: No space left on device");
}

// --resume (docs/farm.md): frames and bands a previous run finished are
// kept as they are (the same file, by inode), missing, damaged or foreign
// ones are rendered again, and the result is what one run writes.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include "tests/cli/farm_scene.hpp"

namespace fs = std::filesystem;

namespace {

ino_t inode(const fs::path& p) {
    struct stat st {};
    REQUIRE(::stat(p.c_str(), &st) == 0);
    return st.st_ino;
}

}  // namespace

TEST_CASE("resuming keeps finished frames and renders missing, damaged and foreign ones") {
    auto dir = test_dir("resume_frames");
    write_file(dir / "scene.sdl", kFarmScene);
    const std::string args = "--frames 4 -W 40 -H 30 -o " + quoted(dir, "a.png");
    render_farm_scene(dir, args);
    std::string first[5];
    for (int i = 1; i <= 4; ++i) first[i] = slurp(dir / ("a_000" + std::to_string(i) + ".png"));
    const ino_t kept = inode(dir / "a_0001.png");
    fs::remove(dir / "a_0002.png");                                     // a killed job: never written
    write_file(dir / "a_0003.png", first[3].substr(0, first[3].size() - 30));  // damaged
    // Frame 4 of another render (other seed) under the same name.
    render_farm_scene(dir, "--frames 4 --frame 4 --spp 4 --seed 3 -W 40 -H 30 -o " + quoted(dir, "a.png"));
    const KerfRun r = run_kerf("render " + quoted(dir, "scene.sdl") + " " + args + " --resume", dir);
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.find((dir / "a_0001.png").string() + ": already rendered, skipped") != std::string::npos);
    CHECK(r.err.find("a_0002.png") == std::string::npos);  // simply rendered
    CHECK(r.err.find((dir / "a_0003.png").string() + ": the file ends early; rendering it again") != std::string::npos);
    CHECK(r.err.find((dir / "a_0004.png").string() +
                     ": written by another render (scene, size, seed or options differ); rendering it again") !=
          std::string::npos);
    CHECK(inode(dir / "a_0001.png") == kept);
    for (int i = 1; i <= 4; ++i) CHECK(slurp(dir / ("a_000" + std::to_string(i) + ".png")) == first[i]);
}

TEST_CASE("resuming a band keeps it only when it is a band of the same render") {
    auto dir = test_dir("resume_band");
    write_file(dir / "scene.sdl", kFarmScene);
    const std::string args = "--tile 1/3 -W 40 -H 30 -o " + quoted(dir, "t.png");
    render_farm_scene(dir, args);
    const ino_t kept = inode(dir / "t_tile1of3.png");
    KerfRun r = run_kerf("render " + quoted(dir, "scene.sdl") + " " + args + " --resume", dir);
    CHECK(r.status == 0);
    CHECK(inode(dir / "t_tile1of3.png") == kept);
    r = run_kerf("render " + quoted(dir, "scene.sdl") + " " + args + " --resume -D '$t=0.5'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find("written by another render") != std::string::npos);
    CHECK(inode(dir / "t_tile1of3.png") != kept);
    // Whole and of this render, but without the table assemble joins by.
    const ino_t again = inode(dir / "t_tile1of3.png");
    hide_pieces_table(dir / "t_tile1of3.png");
    r = run_kerf("render " + quoted(dir, "scene.sdl") + " " + args + " --resume -D '$t=0.5'", dir);
    CHECK(r.status == 0);
    CHECK(r.err.find("has no table of its image data pieces; rendering it again") != std::string::npos);
    CHECK(inode(dir / "t_tile1of3.png") != again);
}

// Two scenes with the same leaves, materials and tree, whose checkers differ
// only in the frame of their material() call (Scene::material_frames): the
// band of one is not a band of the other, since its pixels differ.
TEST_CASE("resuming a band renders it again when only a pattern's frame changed") {
    auto dir = test_dir("resume_pattern_frame");
    auto scene = [](const char* shift) {
        return std::string("camera(position = [0, -6, 2], look_at = [0, 0, 0]);\n") + "translate([" + shift +
               ", 0, 0]) material(color = \"white\", color2 = \"black\", pattern = \"checker\", pattern_scale = 0.5)"
               " translate([-" + shift + ", 0, 0]) sphere(1);\n";
    };
    write_file(dir / "scene.sdl", scene("0.5"));
    const std::string args = "--tile 1/2 -W 40 -H 30 -o " + quoted(dir, "t.png");
    render_farm_scene(dir, args);
    const std::string first = slurp(dir / "t_tile1of2.png");
    write_file(dir / "scene.sdl", scene("0.25"));
    const KerfRun r = run_kerf("render " + quoted(dir, "scene.sdl") + " " + args + " --resume", dir);
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(r.err.find("written by another render") != std::string::npos);
    CHECK(slurp(dir / "t_tile1of2.png") != first);  // the pixels did change
}

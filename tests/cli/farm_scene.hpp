// A small scene whose picture changes with $t (a sphere moving along x,
// in front of a box: no symmetry maps one frame onto another), and its
// render into band files, for the farm tests (docs/farm.md).
#pragma once
#include <string>

#include <zlib.h>

#include "tests/cli/run_kerf.hpp"

constexpr const char* kFarmScene =
    "camera(position = [0, -8, 3], look_at = [0, 0, 0]);\n"
    "light(position = [4, -6, 8]);\n"
    "material(color = \"orange\") translate([4 * $t - 1.5, 0, 0]) sphere(1);\n"
    "material(color = \"steelblue\") difference() { translate([0, 2, 0]) cube([6, 1, 4], center = true);"
    " rotate([90, 0, 0]) cylinder(h = 10, r = 0.7, center = true); }\n";

// Quoted path of `name` in `dir`, for command lines.
inline std::string quoted(const std::filesystem::path& dir, const std::string& name) {
    return "'" + (dir / name).string() + "'";
}

// `kerf render` of the farm scene in `dir` with `args`; REQUIREs success.
inline void render_farm_scene(const std::filesystem::path& dir, const std::string& args) {
    const KerfRun r = run_kerf("render " + quoted(dir, "scene.sdl") + " " + args, dir);
    INFO(args << "\n" << r.err);
    REQUIRE(r.status == 0);
}

// Renames the band file's "kerf pieces" text chunk (the table `kerf
// assemble` joins by) to "kerf_pieces", with a good CRC: a band as an
// older kerf wrote it, whole but without the table.
inline void hide_pieces_table(const std::filesystem::path& path) {
    std::string png = slurp(path);
    const std::size_t key = png.find(std::string("tEXtkerf pieces"));
    REQUIRE(key != std::string::npos);
    png[key + 8] = '_';
    const auto* bytes = reinterpret_cast<const unsigned char*>(png.data());
    const std::size_t length = std::size_t(bytes[key - 4]) << 24 | std::size_t(bytes[key - 3]) << 16 |
                               std::size_t(bytes[key - 2]) << 8 | bytes[key - 1];
    const uLong crc = crc32(0, bytes + key, uInt(4 + length));
    for (int i = 0; i < 4; ++i) png[key + 4 + length + i] = char(crc >> (24 - 8 * i));
    write_file(path, png);
}

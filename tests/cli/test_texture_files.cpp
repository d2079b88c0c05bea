// material(texture = ...) through the real binary (docs/language.md, "Image
// textures"): the image lies in the coordinates of the material() call
// (transforms outside it move it, those inside do not), and a missing or
// unreadable file is a located error while evaluating.
#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

#include "render/image/png_file.hpp"
#include "tests/cli/bad_input_checks.hpp"

namespace fs = std::filesystem;

namespace {

// Quadrants top row first: red, green / blue, white.
void write_quadrants(const fs::path& path) {
    const std::uint8_t px[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    std::vector<unsigned char> file;
    REQUIRE(kerf::render::encode_png(file, px, 2, 2, 3, true).empty());
    write_file(path, std::string(file.begin(), file.end()));
}

// A PFM's pixel (x, y from the top): its rows are stored bottom first.
glm::dvec3 pfm_pixel(const std::string& bytes, int w, int h, int x, int y) {
    std::size_t pos = 0;
    for (int lines = 0; lines < 3; ++pos)
        if (bytes[pos] == '\n') ++lines;
    float c[3];
    std::memcpy(c, bytes.data() + pos + (std::size_t(h - 1 - y) * w + x) * 12, 12);
    return {c[0], c[1], c[2]};
}

}  // namespace

TEST_CASE("a planar texture lands where the material call's frame puts it") {
    auto dir = test_dir("texture_frame");
    write_quadrants(dir / "quad.png");
    // After the outer translate the image covers x ∈ [3, 5], y ∈ [0, 2]
    // (pattern_scale 2); the inner translate moves only the cube.
    const auto script = write_file(dir / "t.sdl",
                                   "camera(position = [4, 1, 10], look_at = [4, 1, 0], up = [0, 1, 0], projection = \"orthographic\", height = 2);\n"
                                   "light(position = [4, 1, 20]);\n"
                                   "translate([3, 0, 0]) material(texture = \"quad.png\", interpolation = \"nearest\", pattern_scale = 2)\n"
                                   "  translate([0, 0, -1]) cube([2, 2, 1]);\n");
    const auto out = (dir / "t.pfm").string();
    const KerfRun r = run_kerf("render '" + script + "' -o '" + out + "' -W 8 -H 8 --spp 1", dir);
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string bytes = slurp(out);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const glm::dvec3 c = pfm_pixel(bytes, 8, 8, x, y);
            INFO(x << " " << y << " " << c.x << " " << c.y << " " << c.z);
            const bool top = y < 4, left = x < 4;
            if (top && left) CHECK((c.x > 5 * c.y && c.x > 5 * c.z));
            if (top && !left) CHECK((c.y > 5 * c.x && c.y > 5 * c.z));
            if (!top && left) CHECK((c.z > 5 * c.x && c.z > 5 * c.y));
            if (!top && !left) CHECK((c.x > 0.1 && std::abs(c.x - c.y) < 1e-3 && std::abs(c.y - c.z) < 1e-3));
        }
}

TEST_CASE("a missing or unreadable texture is a located error at evaluation") {
    auto dir = test_dir("texture_bad");
    const auto missing = write_file(dir / "missing.sdl", "cube(1);\nmaterial(texture = \"nope.png\") cube(1);\n");
    const Located head = reject(missing, dir);
    CHECK(head.line == 2);
    CHECK(head.col == 1);
    CHECK(head.message.find("nope.png") != std::string::npos);
    write_file(dir / "junk.png", "this is not an image");
    const auto junk = write_file(dir / "junk.sdl", "material(texture = \"junk.png\") sphere(1);\n");
    const Located bad = reject(junk, dir);
    CHECK(bad.line == 1);
    CHECK(bad.message.find("cannot read texture") != std::string::npos);
    write_quadrants(dir / "quad.png");
    expect_error(write_file(dir / "map.sdl", "material(texture = \"quad.png\", mapping = \"cubic\") sphere(1);\n"), dir, 1, 1,
                 "material: mapping must be one of \"planar\", \"spherical\", \"cylindrical\"");
}

// import() is bounded like a scene file (docs/language.md §13): a mesh file (any format)
// longer than 256 MiB, or whose header declares more than its size holds, is
// an error located at the import, found before the data is read — exit 1 at
// once and in little memory, checked here under a 200 MB address-space limit
// and a 10 s timeout (the files are sparse: they cost no disk).
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>

#include "tests/cli/bad_input_checks.hpp"

namespace fs = std::filesystem;

namespace {

const Bounds kTight{10, 200'000};

// A sparse file of `size` bytes that begins with `head`.
std::string sparse_file(const fs::path& path, const std::string& head, std::uint64_t size) {
    write_file(path, head);
    fs::resize_file(path, size);
    return path.string();
}

std::string importing(const fs::path& dir, const std::string& file) {
    return write_file(dir / "scene.sdl", "cube(1);\n  import(\"" + file + "\");\n");
}

}  // namespace

TEST_CASE("a 2 GiB STL is refused at the import without being read", "[import][limits]") {
    // It used to be read whole first: 3.9 GB at the peak and 10-30 s.
    const auto dir = test_dir("import_huge");
    sparse_file(dir / "big.stl", "", std::uint64_t(2) << 30);
    expect_error(importing(dir, "big.stl"), dir, 2, 3,
                 "import(\"big.stl\"): longer than 256 MiB (2147483648 bytes), too large to import", "", kTight);
}

TEST_CASE("a binary STL header counting more triangles than the file holds is refused before reading",
          "[import][limits]") {
    const auto dir = test_dir("import_lying_stl");
    std::string head = "binary STL";
    head.resize(80, ' ');
    head += std::string("\xff\xff\xff\xff", 4);
    sparse_file(dir / "lying.stl", head, std::uint64_t(200) << 20);
    expect_error(importing(dir, "lying.stl"), dir, 2, 3,
                 "import(\"lying.stl\"): binary STL header counts 4294967295 triangles (214748364834 bytes) but "
                 "the file has 209715200 bytes",
                 "", kTight);
}

TEST_CASE("PLY element counts are checked against the file's size before the body is read", "[import][limits]") {
    const auto dir = test_dir("import_lying_ply");
    const std::string head =
        "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    sparse_file(dir / "lying.ply", head, std::uint64_t(200) << 20);
    // 10^8 vertices of 12 bytes need 1.2 GB.
    expect_error(importing(dir, "lying.ply"), dir, 2, 3,
                 "import(\"lying.ply\"): the file declares 100000000 vertex elements but only " +
                     std::to_string((std::uint64_t(200) << 20) - head.size()) + " bytes follow (truncated?)",
                 "", kTight);
}

TEST_CASE("OFF, AMF and 3MF files longer than the bound are refused before they are read", "[import][limits]") {
    const auto dir = test_dir("import_huge_formats");
    for (const char* name : {"big.off", "big.amf", "big.3mf"}) {
        INFO(name);
        sparse_file(dir / name, "", std::uint64_t(2) << 30);
        expect_error(importing(dir, name), dir, 2, 3,
                     "import(\"" + std::string(name) + "\"): longer than 256 MiB (2147483648 bytes), too large to import",
                     "", kTight);
    }
}

TEST_CASE("OFF counts are checked against the file's size before the vertices are read", "[import][limits]") {
    const auto dir = test_dir("import_lying_off");
    const std::string head = "OFF\n100000000 1 0\n";
    sparse_file(dir / "lying.off", head, std::uint64_t(200) << 20);
    // 10^8 vertices need 600 MB of text ("0 0 0\n" each) and 2.4 GB as points.
    expect_error(importing(dir, "lying.off"), dir, 2, 3,
                 "import(\"lying.off\"): the file declares 100000000 vertices but only " +
                     std::to_string((std::uint64_t(200) << 20) - head.size()) + " bytes follow (truncated?)",
                 "", kTight);
}

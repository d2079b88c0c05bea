// import() of STL, OBJ and PLY files (docs/spec.md §4): every encoding yields the
// same closed unit cube, checked against closed-form volume, area and bounds;
// broken files are located errors naming the place inside the file.
#include <catch2/catch.hpp>

#include <array>
#include <cstring>
#include <filesystem>
#include <functional>

#include "tests/interpreter/eval_helpers.hpp"
#include "tests/interpreter/import/mesh_files.hpp"
#include "tests/interpreter/temp_tree.hpp"

using kerf::test::TempTree;
using namespace kerf::test::mesh_files;

namespace {

std::vector<std::array<int, 3>> triangles() {
    std::vector<std::array<int, 3>> t;
    for (const auto& q : kQuads) {
        t.push_back({q[0], q[1], q[2]});
        t.push_back({q[0], q[2], q[3]});
    }
    return t;
}

std::string num(double x) { return std::to_string(x); }

std::string ascii_stl() {
    std::string s = "solid cube exported by a test\n";
    for (const auto& t : triangles()) {
        s += "  facet normal 0 0 0\n    outer loop\n";
        for (int i : t) s += "      vertex " + num(kCorners[i].x) + " " + num(kCorners[i].y) + " " + num(kCorners[i].z) + "\n";
        s += "    endloop\n  endfacet\n";
    }
    return s + "endsolid cube\n";
}

void put_le(std::string& s, const void* p, std::size_t n) { s.append(static_cast<const char*>(p), n); }

std::string binary_stl() {
    std::string s = "solid header that lies: this file is binary";
    s.resize(80, ' ');
    const std::uint32_t n = 12;
    put_le(s, &n, 4);
    for (const auto& t : triangles()) {
        const float normal[3] = {0, 0, 0};
        put_le(s, normal, 12);
        for (int i : t) {
            const float v[3] = {float(kCorners[i].x), float(kCorners[i].y), float(kCorners[i].z)};
            put_le(s, v, 12);
        }
        const std::uint16_t attr = 0;
        put_le(s, &attr, 2);
    }
    return s;
}

// Quads, every corner syntax, negative indices, and lines kerf skips.
std::string obj() {
    std::string s = "# cube\nmtllib cube.mtl\no cube\n";
    for (const auto& c : kCorners) s += "v " + num(c.x) + " " + num(c.y) + " " + num(c.z) + "\n";
    s += "vt 0 0\nvn 0 0 1\ng sides\nusemtl grey\ns off\n";
    const char* forms[] = {"%d", "%d/1", "%d//1", "%d/1/1"};
    int k = 0;
    for (const auto& q : kQuads) {
        s += "f";
        for (int i : q) {
            char buf[32];
            const int idx = (k % 2) ? i - 8 : i + 1;  // odd faces count back from the last vertex
            std::snprintf(buf, sizeof buf, forms[k % 4], idx);
            s += std::string(" ") + buf;
        }
        s += "   # face " + std::to_string(k++) + "\n";
    }
    return s;
}

std::string ply_header(const std::string& format) {
    return "ply\nformat " + format + " 1.0\ncomment made by a test\nelement vertex 8\nproperty float x\n"
           "property float y\nproperty double z\nproperty uchar red\nelement face 6\n"
           "property list uchar int vertex_indices\nproperty short flags\nelement edge 1\n"
           "property int vertex1\nproperty int vertex2\nend_header\n";
}

std::string ply_ascii() {
    std::string s = ply_header("ascii");
    for (const auto& c : kCorners) s += num(c.x) + " " + num(c.y) + " " + num(c.z) + " 255\n";
    for (const auto& q : kQuads) s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " +
                                      std::to_string(q[2]) + " " + std::to_string(q[3]) + " -7\n";
    return s + "0 1\n";
}

template <class T>
void put(std::string& s, T v, bool big) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (big) std::reverse(b, b + sizeof(T));
    s.append(b, sizeof(T));
}

std::string ply_binary(bool big) {
    std::string s = ply_header(big ? "binary_big_endian" : "binary_little_endian");
    for (const auto& c : kCorners) {
        put<float>(s, float(c.x), big);
        put<float>(s, float(c.y), big);
        put<double>(s, c.z, big);
        put<std::uint8_t>(s, 255, big);
    }
    for (const auto& q : kQuads) {
        put<std::uint8_t>(s, 4, big);
        for (int i : q) put<std::int32_t>(s, i, big);
        put<std::int16_t>(s, -7, big);
    }
    put<std::int32_t>(s, 0, big);
    put<std::int32_t>(s, 1, big);
    return s;
}

}  // namespace

TEST_CASE("every mesh encoding imports as the same closed cube in OpenSCAD's face order", "[import]") {
    TempTree t;
    const std::pair<const char*, std::string> files[] = {
        {"cube.stl", ascii_stl()},  {"binary.STL", binary_stl()},      {"cube.obj", obj()},
        {"cube.ply", ply_ascii()},  {"le.ply", ply_binary(false)},     {"be.ply", ply_binary(true)}};
    for (const auto& [name, bytes] : files) {
        INFO(name);
        t.write(std::string("meshes/") + name, bytes);
        const std::string script = t.write("scene.sdl", std::string("import(\"meshes/") + name + "\");\n");
        kerf::EvalResult r = eval_file(script);
        REQUIRE(r.graph.meshes.size() == 1);
        const Measures m = measure(r.graph.meshes[0]);
        CHECK(m.volume == Approx(-1.0));  // clockwise from outside, like polyhedron()
        CHECK(m.area == Approx(6.0));
        CHECK(m.lo == glm::dvec3(0));
        CHECK(m.hi == glm::dvec3(1));
        CHECK(r.graph.meshes[0].solid);
        auto leaves = kerf::test::leaves(r.graph);
        REQUIRE(leaves.size() == 1);
        CHECK(leaves[0].prim == kerf::csg::PrimKind::Mesh);
    }
}

TEST_CASE("import takes solid = false, and a loop reads the file once", "[import]") {
    TempTree t;
    t.write("cube.stl", ascii_stl());
    kerf::EvalResult r = eval_file(t.write("a.sdl", "for (i = [0:9]) translate([2 * i, 0, 0]) import(\"cube.stl\");\n"
                                                  "import(file = \"cube.stl\", solid = false);\n"));
    REQUIRE(r.graph.meshes.size() == 2);
    CHECK(r.graph.meshes[0].solid);
    CHECK_FALSE(r.graph.meshes[1].solid);
    CHECK(kerf::test::leaves(r.graph).size() == 11);
}

TEST_CASE("broken mesh files are errors located at the import and inside the file", "[import][errors]") {
    TempTree t;
    auto err = [&](const std::string& name, const std::string& bytes) {
        t.write(name, bytes);
        return error_in(t.write("s.sdl", "\n  import(\"" + name + "\");\n"));
    };
    const std::string stl = ascii_stl();
    CHECK(err("cut.stl", stl.substr(0, stl.find("vertex 1") + 9)) ==
          "2:3: error: import(\"cut.stl\"): line 6: expected a vertex coordinate, got the end of the file");
    CHECK(err("typo.stl", "solid x\n facet nrmal 0 0 1\n") ==
          "2:3: error: import(\"typo.stl\"): line 2: expected 'normal', got 'nrmal'");
    CHECK(err("short.stl", binary_stl().substr(0, 200)) ==
          "2:3: error: import(\"short.stl\"): binary STL header counts 12 triangles (684 bytes) but the file "
          "has 200 bytes");
    CHECK(err("garbage.stl", std::string("\x01\x02\x00zz", 5)) ==
          "2:3: error: import(\"garbage.stl\"): not an STL file (shorter than a binary STL header, no 'solid')");
    CHECK(err("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n") ==
          "2:3: error: import(\"bad.obj\"): line 4: vertex index 9 refers to no vertex (3 defined so far)");
    CHECK(err("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") ==
          "2:3: error: import(\"nan.obj\"): a vertex is not finite");
    CHECK(err("empty.obj", "# nothing\n") == "2:3: error: import(\"empty.obj\"): the file holds no faces");
    const std::string ply = ply_binary(false);
    CHECK(err("cut.ply", ply.substr(0, ply.size() - 20)) ==
          "2:3: error: import(\"cut.ply\"): the file declares 4 list items but only 6 bytes follow (truncated?)");
    CHECK(err("cut2.ply", ply.substr(0, ply.size() - 3)) == "2:3: error: import(\"cut2.ply\"): byte " +
                                                              std::to_string(ply.size() - 4) +
                                                              ": the file ends inside the data (truncated?)");
    CHECK(err("huge.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\nend_header\n1\n") ==
          "2:3: error: import(\"huge.ply\"): the file declares 1000000000000 vertex elements but only 2 bytes "
          "follow (truncated?)");
    CHECK(err("noformat.ply", "ply\nelement vertex 0\nend_header\n") ==
          "2:3: error: import(\"noformat.ply\"): the PLY header has no 'format' line");
    CHECK(err("m.xyz", "whatever") ==
          "2:3: error: import(\"m.xyz\"): unknown mesh format '.xyz' (kerf reads .stl, .obj, .ply, .off, .amf and .3mf)");
    CHECK(error_in(t.write("s.sdl", "import(\"missing.stl\");\n")) == "1:1: error: cannot find 'missing.stl'");
    CHECK(error_in(t.write("s.sdl", "import(3);\n")).find("file must be a string") != std::string::npos);
}

TEST_CASE("the list limit bounds the faces a file may bring", "[import][limits]") {
    TempTree t;
    t.write("cube.stl", ascii_stl());
    t.write("cube.ply", ply_binary(false));
    kerf::EvalOptions opt;
    opt.limits.list_elements = 5;
    CHECK(error_in(t.write("s.sdl", "import(\"cube.stl\");\n"), opt) ==
          "1:1: error: import(\"cube.stl\"): line 37: more than 5 triangles (--max-list)");
    CHECK(error_in(t.write("s.sdl", "import(\"cube.ply\");\n"), opt) ==
          "1:1: error: import(\"cube.ply\"): the file declares 6 face elements, more than the limit 5 (--max-list)");
}

TEST_CASE("a file longer than the import bound is refused before it is read", "[import][limits]") {
    // Sparse: 2 GiB of file costs no disk. It used to be read whole (3.8 GB
    // at the peak) before its header was found wrong.
    TempTree t;
    const std::string big = t.write("big.stl", "");
    std::filesystem::resize_file(big, std::uint64_t(2) << 30);
    CHECK(error_in(t.write("s.sdl", "\n  import(\"big.stl\");\n")) ==
          "2:3: error: import(\"big.stl\"): longer than 256 MiB (2147483648 bytes), too large to import");
}

TEST_CASE("a binary STL's count and a PLY's element counts are checked against the file's size first",
          "[import][limits]") {
    TempTree t;
    // Below the bound, but a header claiming 2^32 - 1 triangles.
    std::string lying = "binary STL";
    lying.resize(80, ' ');
    lying += std::string("\xff\xff\xff\xff", 4);
    const std::string stl = t.write("lying.stl", lying);
    std::filesystem::resize_file(stl, std::uint64_t(200) << 20);
    CHECK(error_in(t.write("s.sdl", "import(\"lying.stl\");\n")) ==
          "1:1: error: import(\"lying.stl\"): binary STL header counts 4294967295 triangles (214748364834 bytes) "
          "but the file has 209715200 bytes");
    // Each vertex takes 4 + 4 + 8 + 1 bytes, each face at least its list
    // length: 8 vertices need 136 bytes, and 135 follow.
    const std::string ply = ply_binary(false);
    const std::size_t body = ply_header("binary_little_endian").size();
    CHECK(err_of(t, "short.ply", ply.substr(0, body + 135)) ==
          "import(\"short.ply\"): the file declares 8 vertex elements but only 135 bytes follow (truncated?)");
    CHECK(err_of(t, "faces.ply", ply.substr(0, body + 136 + 5)) ==
          "import(\"faces.ply\"): the file declares 6 face elements but only 5 bytes follow (truncated?)");
    // An element without properties holds no data, however large its count.
    std::string empty_element = ply_ascii();
    empty_element.insert(empty_element.find("end_header"), "element junk 1000000000000\n");
    t.write("junk.ply", empty_element);
    CHECK(eval_file(t.write("s.sdl", "import(\"junk.ply\");\n")).graph.meshes.at(0).faces.size() == 6);
}

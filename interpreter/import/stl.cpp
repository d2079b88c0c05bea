// STL, binary (80-byte header, triangle count, 50 bytes per triangle) and
// ASCII (solid / facet normal / outer loop / vertex ... ). STL has no shared
// vertices: each triangle brings its own three points.
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "interpreter/import/mesh_import.hpp"
#include "interpreter/import/formats.hpp"

namespace kerf::eval::mesh_format {

namespace {

std::uint32_t le_u32(const char* p) {
    const auto* b = reinterpret_cast<const unsigned char*>(p);
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

float le_f32(const char* p) {
    std::uint32_t u = le_u32(p);
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

// Streamed: a batch of records at a time, so the file's bytes are never all
// in memory beside the mesh made of them.
graph::PolygonMesh read_binary(const MeshFile& file, std::uint64_t count, std::uint64_t max_faces) {
    check_count(count, file.size() - 84, 50, "triangles", max_faces);
    graph::PolygonMesh m;
    m.points.reserve(3 * count);
    m.faces.reserve(count);
    constexpr std::uint64_t kBatch = 4096;  // records per read: 200 KiB
    std::vector<char> records(50 * kBatch);
    for (std::uint64_t first = 0; first < count; first += kBatch) {
        const std::uint64_t n = std::min(kBatch, count - first);
        file.read_exact(84 + 50 * first, records.data(), 50 * n);
        for (std::uint64_t t = 0; t < n; ++t) {
            const char* rec = records.data() + 50 * t + 12;  // skip the stored normal: the winding decides
            std::vector<std::uint32_t> face;
            for (int v = 0; v < 3; ++v) {
                const char* p = rec + 12 * v;
                face.push_back(static_cast<std::uint32_t>(m.points.size()));
                m.points.emplace_back(le_f32(p), le_f32(p + 4), le_f32(p + 8));
            }
            m.faces.push_back(std::move(face));
        }
    }
    return m;
}

graph::PolygonMesh read_ascii(std::string_view bytes, std::uint64_t max_faces) {
    Tokens in(bytes);
    graph::PolygonMesh m;
    in.expect("solid");
    in.skip_line();  // the solid's name
    for (;;) {
        std::string_view t = in.next();
        if (t == "endsolid") {
            in.skip_line();
            if (in.at_end()) break;
            in.expect("solid");  // files may hold several solids
            in.skip_line();
            continue;
        }
        if (t != "facet") in.fail("expected 'facet' or 'endsolid', got " + Tokens::quoted(t));
        if (m.faces.size() >= max_faces)
            in.fail_limit("more than " + std::to_string(max_faces) + " triangles (--max-list)");
        in.expect("normal");
        for (int i = 0; i < 3; ++i) in.number("a normal coordinate");
        in.expect("outer");
        in.expect("loop");
        std::vector<std::uint32_t> face;
        for (t = in.next(); t == "vertex"; t = in.next()) {
            double x = in.number("a vertex coordinate");
            double y = in.number("a vertex coordinate");
            double z = in.number("a vertex coordinate");
            face.push_back(static_cast<std::uint32_t>(m.points.size()));
            m.points.emplace_back(x, y, z);
        }
        if (t != "endloop") in.fail("expected 'vertex' or 'endloop'");
        if (face.size() < 3) in.fail("a facet needs 3 vertices, got " + std::to_string(face.size()));
        in.expect("endfacet");
        m.faces.push_back(std::move(face));
    }
    return m;
}

}  // namespace

graph::PolygonMesh read_stl(const MeshFile& file, std::uint64_t max_faces) {
    // A binary file's header may begin with "solid" too: the size decides,
    // and control bytes tell a broken binary file from a broken ASCII one.
    // The header and the size alone settle a binary file, before any
    // triangle is read.
    const std::string head = file.read(0, 84);
    const bool solid = head.substr(0, 5) == "solid";
    const auto mismatch = [&](std::uint64_t count) {
        return MeshFormatError("binary STL header counts " + std::to_string(count) + " triangles (" +
                               std::to_string(84 + 50 * count) + " bytes) but the file has " +
                               std::to_string(file.size()) + " bytes");
    };
    std::uint64_t count = 0;
    if (head.size() == 84) {
        count = le_u32(head.data() + 80);
        if (file.size() == 84 + 50 * count) return read_binary(file, count, max_faces);
        if (!solid) throw mismatch(count);
    }
    if (!solid) throw MeshFormatError("not an STL file (shorter than a binary STL header, no 'solid')");
    const std::string bytes = file.read_all();
    const bool text = std::none_of(bytes.begin(), bytes.end(), [](char c) {
        return (c >= 0 && c < 9) || (c > 13 && c < 32);
    });
    if (!text && head.size() == 84) throw mismatch(count);
    return read_ascii(bytes, max_faces);
}

}  // namespace kerf::eval::mesh_format

// OFF (Object File Format), as OpenSCAD 2021.01 reads it through CGAL: a
// header word OFF (with the optional ST, C and N prefixes of texture
// coordinates, colours and normals), the counts 'vertices faces [edges]',
// one vertex per line ('x y z', the rest of the line dropped), one face
// per line ('n i1 ... in', 0-based; a colour after the indices dropped).
// Faces are polygons, concave or not planar: lowering triangulates them
// (docs/lowering.md). '#' starts a comment; blank lines are skipped.
#include <algorithm>

#include "interpreter/import/formats.hpp"
#include "interpreter/import/mesh_import.hpp"

namespace kerf::eval::mesh_format {

namespace {

// A count or an index: a whole number from 0 below 2^32 - 1; `tok` is
// the token read (for the caller's messages).
std::uint32_t whole(Tokens& t, const char* what, std::string_view& tok) {
    tok = t.next();
    double v = 0;
    if (!parse_number(tok, v) || !(v >= 0 && v < 4294967295.0) || v != static_cast<double>(static_cast<std::uint32_t>(v)))
        t.fail(std::string("expected ") + what + ", got " + Tokens::quoted(tok));
    return static_cast<std::uint32_t>(v);
}

// The header and the counts: the vertex and face counts, and the offset of
// the line after them.
struct Counts {
    std::uint32_t nv = 0, nf = 0;
    std::size_t body = 0;
};

Counts read_counts(std::string_view bytes) {
    Lines lines(bytes);
    Tokens in = lines.need("the header 'OFF'");
    std::string_view word = in.next();
    std::string_view kind = word;
    for (std::string_view prefix : {"ST", "C", "N"})
        if (kind.substr(0, prefix.size()) == prefix) kind.remove_prefix(prefix.size());
    if (kind == "4OFF" || kind == "nOFF") in.fail("'" + std::string(word) + "' (points not in 3D) is not read");
    if (kind != "OFF") in.fail("not an OFF file: expected the header 'OFF', got " + Tokens::quoted(word));
    // The counts may follow on the header's line (OpenSCAD reads that too).
    if (in.at_end()) in = lines.need("the counts 'vertices faces edges'");
    else if (Tokens peek = in; peek.next() == "BINARY") in.fail("binary OFF is not read (only the text form)");
    Counts c;
    std::string_view tok;
    c.nv = whole(in, "a vertex count", tok);
    c.nf = whole(in, "a face count", tok);
    c.body = bytes.size() - lines.left();
    return c;
}

}  // namespace

graph::PolygonMesh read_off(const MeshFile& file, std::uint64_t max_faces) {
    // The header and counts come first, read by themselves (a long comment
    // before them: the whole file), so counts the file cannot hold are
    // refused before the body is read.
    std::string bytes = file.read(0, 65536);
    Counts c;
    try {
        c = read_counts(bytes);
    } catch (const MeshFormatError&) {
        if (bytes.size() == file.size()) throw;
        c.body = bytes.size();
    }
    if (c.body >= bytes.size() && bytes.size() < file.size()) {  // the counts may run on past the part read
        bytes = file.read_all();
        c = read_counts(bytes);
    }
    const std::uint64_t nv = c.nv, nf = c.nf, left = file.size() - c.body;
    // Each vertex line takes at least "0 0 0\n", each face "3 0 1 2\n"; the
    // last line needs no newline.
    check_count(nv, left, 6, "vertices", ~std::uint64_t(0), 1);
    check_count(nf, left - std::min<std::uint64_t>(left, 6 * nv), 8, "faces", max_faces, 1);
    if (bytes.size() < file.size()) bytes = file.read_all();
    Lines lines(bytes, c.body);
    std::string_view tok;
    graph::PolygonMesh m;
    m.points.reserve(nv);
    for (std::uint64_t i = 0; i < nv; ++i) {
        Tokens v = lines.need("a vertex");
        const double x = v.number("a vertex coordinate");
        const double y = v.number("a vertex coordinate");
        const double z = v.number("a vertex coordinate");
        m.points.emplace_back(x, y, z);  // colours, normals, texture coordinates may follow
    }
    m.faces.reserve(nf);
    for (std::uint64_t i = 0; i < nf; ++i) {
        Tokens f = lines.need("a face");
        const std::uint32_t n = whole(f, "a face's corner count", tok);
        if (n < 3) f.fail("a face needs at least 3 corners, got " + std::to_string(n));
        std::vector<std::uint32_t> face;
        for (std::uint32_t k = 0; k < n; ++k) {
            const std::uint32_t idx = whole(f, "a vertex index", tok);
            if (idx >= nv)
                f.fail("face " + std::to_string(i) + " refers to vertex " + std::string(tok) + " (there are " +
                       std::to_string(nv) + ")");
            face.push_back(idx);
        }
        m.faces.push_back(std::move(face));  // a colour may follow
    }
    return m;
}

}  // namespace kerf::eval::mesh_format

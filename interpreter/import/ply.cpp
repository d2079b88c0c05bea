// PLY (ascii, binary_little_endian, binary_big_endian): the header declares
// elements and their properties; the 'vertex' element's x, y, z and the
// 'face' element's vertex_indices (or vertex_index) list define the mesh.
// Other elements and properties are read past and dropped.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

#include "interpreter/import/mesh_import.hpp"
#include "interpreter/import/formats.hpp"

namespace kerf::eval::mesh_format {

namespace {

enum class Format { Ascii, Little, Big };

struct Property {
    std::string name;
    int size = 0;            // bytes of a scalar (or of the list's items)
    bool is_float = false, is_signed = false;
    bool list = false;
    int count_size = 0;      // bytes of a list's length
    bool count_signed = false;
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> props;
};

// Scalar type names of the PLY header: size, float, signed.
bool scalar_type(std::string_view t, int& size, bool& is_float, bool& is_signed) {
    struct T { std::string_view a, b; int size; bool f, s; };
    static const T types[] = {{"char", "int8", 1, false, true},     {"uchar", "uint8", 1, false, false},
                              {"short", "int16", 2, false, true},   {"ushort", "uint16", 2, false, false},
                              {"int", "int32", 4, false, true},     {"uint", "uint32", 4, false, false},
                              {"float", "float32", 4, true, true},  {"double", "float64", 8, true, true}};
    for (const T& x : types)
        if (t == x.a || t == x.b) {
            size = x.size, is_float = x.f, is_signed = x.s;
            return true;
        }
    return false;
}

// Reads scalars from the body: tokens for ascii, bytes for the binary formats.
class Body {
public:
    Body(std::string_view bytes, std::size_t start, Format f) : bytes_(bytes), pos_(start), fmt_(f), tok_(bytes, start) {}

    double read(int size, bool is_float, bool is_signed) {
        if (fmt_ == Format::Ascii) return tok_.number("a number");
        if (bytes_.size() - pos_ < static_cast<std::size_t>(size))
            throw MeshFormatError("byte " + std::to_string(pos_) + ": the file ends inside the data (truncated?)");
        unsigned char b[8];
        std::memcpy(b, bytes_.data() + pos_, static_cast<std::size_t>(size));
        pos_ += static_cast<std::size_t>(size);
        if ((fmt_ == Format::Big) == (std::endian::native == std::endian::little))
            for (int i = 0; i < size / 2; ++i) std::swap(b[i], b[size - 1 - i]);
        if (is_float) {
            if (size == 4) { float f; std::memcpy(&f, b, 4); return f; }
            double d; std::memcpy(&d, b, 8); return d;
        }
        std::uint64_t u = 0;
        std::memcpy(&u, b, static_cast<std::size_t>(size));  // little-endian host: low bytes first
        if (is_signed && size < 8 && (u >> (8 * size - 1)) & 1) return static_cast<double>(u) - std::ldexp(1.0, 8 * size);
        return static_cast<double>(u);
    }

    // Bytes not yet read (for ascii: from the body's start, a generous bound).
    std::size_t left() const { return bytes_.size() - pos_; }
    [[noreturn]] void fail(const std::string& msg) {
        if (fmt_ == Format::Ascii) tok_.fail(msg);
        throw MeshFormatError("byte " + std::to_string(pos_) + ": " + msg);
    }

private:
    std::string_view bytes_;
    std::size_t pos_;
    Format fmt_;
    Tokens tok_;
};

// The header: format, elements with their properties, where the data starts.
struct Header {
    Format fmt = Format::Ascii;
    std::vector<Element> elements;
    std::size_t body_start = 0;
};

Header read_header(std::string_view bytes) {
    std::size_t header_end = bytes.find("end_header");
    if (bytes.substr(0, 3) != "ply" || header_end == std::string_view::npos)
        throw MeshFormatError("not a PLY file (no 'ply' ... 'end_header' header)");
    Tokens hdr(bytes.substr(0, header_end));
    hdr.expect("ply");
    Header h;
    bool have_format = false;
    for (std::string_view key = hdr.next(); !key.empty(); key = hdr.next()) {
        if (key == "comment" || key == "obj_info") {
            hdr.skip_line();
        } else if (key == "format") {
            std::string_view f = hdr.next();
            if (f == "ascii") h.fmt = Format::Ascii;
            else if (f == "binary_little_endian") h.fmt = Format::Little;
            else if (f == "binary_big_endian") h.fmt = Format::Big;
            else hdr.fail("unknown PLY format " + Tokens::quoted(f));
            hdr.skip_line();
            have_format = true;
        } else if (key == "element") {
            Element e;
            e.name = hdr.next();
            double n = hdr.number("an element count");
            if (n < 0 || n != static_cast<double>(static_cast<std::uint64_t>(n))) hdr.fail("bad element count");
            e.count = static_cast<std::uint64_t>(n);
            h.elements.push_back(std::move(e));
        } else if (key == "property") {
            if (h.elements.empty()) hdr.fail("a property before any element");
            Property p;
            std::string_view t = hdr.next();
            if (t == "list") {
                p.list = true;
                bool cf = false;
                if (!scalar_type(hdr.next(), p.count_size, cf, p.count_signed) || cf) hdr.fail("bad list count type");
                t = hdr.next();
            }
            if (!scalar_type(t, p.size, p.is_float, p.is_signed))
                hdr.fail("unknown property type " + Tokens::quoted(t));
            p.name = hdr.next();
            h.elements.back().props.push_back(std::move(p));
        } else {
            hdr.fail("unexpected " + Tokens::quoted(key) + " in the PLY header");
        }
    }
    if (!have_format) throw MeshFormatError("the PLY header has no 'format' line");
    const std::size_t eol = bytes.find('\n', header_end);
    h.body_start = eol == std::string_view::npos ? bytes.size() : eol + 1;
    return h;
}

// The fewest bytes one element of `e` takes: binary, its scalars and list
// lengths (a list may be empty); ascii, a digit and a separator each.
std::uint64_t min_element_bytes(const Element& e, Format fmt) {
    std::uint64_t bytes = 0;
    for (const Property& p : e.props) bytes += fmt == Format::Ascii ? 2 : p.list ? p.count_size : p.size;
    return bytes;
}

// The header, read by itself (it is short; the search for its end doubles
// the bytes read each round), and every element count checked against the
// bytes after it, before the body is read.
Header read_checked_header(const MeshFile& file, std::uint64_t max_faces) {
    std::string head;
    for (std::size_t n = 4096;; n *= 2) {
        head = file.read(0, n);
        const std::size_t end = head.find("end_header");
        if (head.size() < n || (end != std::string::npos && head.find('\n', end) != std::string::npos)) break;
    }
    Header h = read_header(head);
    std::uint64_t left = file.size() - h.body_start;
    for (const Element& e : h.elements) {
        const std::uint64_t min = min_element_bytes(e, h.fmt);
        if (min == 0) continue;  // no properties: no data, whatever the count
        // ascii: the last number of the file needs no separator after it
        check_count(e.count, left, min, e.name + " elements", e.name == "face" ? max_faces : ~std::uint64_t(0),
                    h.fmt == Format::Ascii ? 1 : 0);
        left -= std::min(left, e.count * min);
    }
    return h;
}

}  // namespace

graph::PolygonMesh read_ply(const MeshFile& file, std::uint64_t max_faces) {
    const Header h = read_checked_header(file, max_faces);
    const std::string bytes = file.read_all();
    const Format fmt = h.fmt;
    Body body(bytes, h.body_start, fmt);
    graph::PolygonMesh m;
    for (const Element& e : h.elements) {
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
        if (e.props.empty() && !is_vertex) continue;  // no data, however many: nothing to read
        for (std::uint64_t i = 0; i < e.count; ++i) {
            glm::dvec3 v(0);
            int xyz = 0;
            for (const Property& p : e.props) {
                if (!p.list) {
                    double x = body.read(p.size, p.is_float, p.is_signed);
                    if (is_vertex && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z') {
                        v[p.name[0] - 'x'] = x;
                        xyz |= 1 << (p.name[0] - 'x');
                    }
                    continue;
                }
                double n = body.read(p.count_size, false, p.count_signed);
                if (n < 0) body.fail("negative list length");
                check_count(static_cast<std::uint64_t>(n), body.left(), fmt == Format::Ascii ? 2 : p.size, "list items",
                            ~std::uint64_t(0), fmt == Format::Ascii ? 1 : 0);
                const bool indices = is_face && (p.name == "vertex_indices" || p.name == "vertex_index");
                std::vector<std::uint32_t> face;
                for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(n); ++k) {
                    double idx = body.read(p.size, p.is_float, p.is_signed);
                    if (!indices) continue;
                    if (idx < 0 || idx >= 4294967295.0 || idx != static_cast<double>(static_cast<std::uint32_t>(idx)))
                        body.fail("bad vertex index " + std::to_string(idx));
                    face.push_back(static_cast<std::uint32_t>(idx));
                }
                if (indices) m.faces.push_back(std::move(face));
            }
            if (is_vertex) {
                if (xyz != 7) throw MeshFormatError("the vertex element lacks an x, y or z property");
                m.points.push_back(v);
            }
        }
    }
    return m;
}

}  // namespace kerf::eval::mesh_format

// AMF (Additive Manufacturing File Format, XML), streamed with libxml2's
// reader as OpenSCAD 2021.01 reads it: every <object>'s mesh is one part
// (the triangles of all its <volume>s together, indices into the object's
// <vertices>), the parts united. Metadata, materials and colours do not
// define the solid and are skipped; curved triangles (<edge> tangents) are
// read flat and <constellation>s not placed, each with a warning. The
// root's unit scales to millimetres, except in OpenSCAD's reading (it
// ignores the unit; a warning says so when it is not millimetres). In the
// XML module (xml_module.hpp), on the file's bytes (unzipped by kerf).
#include <cmath>
#include <cstring>
#include <map>
#include <memory>

#include <libxml/xmlreader.h>

#include "interpreter/import/formats.hpp"
#include "interpreter/import/xml_module/xml_module.hpp"

namespace kerf::eval::mesh_format {

namespace {

// The millimetres of one AMF unit, or 0 for a name AMF does not define.
double unit_mm(const std::string& u) {
    if (u.empty() || u == "millimeter") return 1;
    if (u == "inch") return 25.4;
    if (u == "feet") return 304.8;
    if (u == "meter") return 1000;
    if (u == "micron" || u == "micrometer") return 0.001;
    return 0;
}

// libxml2 reports every error; the first fatal one says what is wrong.
void keep_first_fatal(void* slot, xmlErrorPtr e) {
    auto* first = static_cast<std::string*>(slot);
    if (e && e->level == XML_ERR_FATAL && first->empty()) {
        std::string msg = e->message ? e->message : "unreadable";
        while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
        *first = "line " + std::to_string(e->line) + ": " + msg;
    }
}

class AmfReader {
public:
    AmfReader(xmlTextReaderPtr r, const MeshReading& how) : r_(r), how_(how) {}

    void start(const std::string& name, bool empty) {
        const std::size_t depth = path_.size();
        if (depth == 0) {
            if (name != "amf") fail("not an AMF file: the root element is <" + name + ">, not <amf>");
            unit_ = attribute("unit");
        } else if (at({"amf"}) && name == "object") {
            out_.parts.emplace_back();
        } else if (at({"amf", "object", "mesh", "vertices"}) && name == "vertex") {
            have_ = 0;
        } else if (at({"amf", "object", "mesh", "volume"}) && name == "triangle") {
            have_ = 0;
        } else if (name == "edge" || name == "constellation") {
            ignored_.try_emplace(name, line());
        }
        path_.push_back(name);
        text_.clear();
        if (empty) end();
    }

    void text(const char* t) { text_ += t; }

    void end() {
        const std::string name = path_.back();
        path_.pop_back();
        if (at({"amf", "object", "mesh", "vertices", "vertex", "coordinates"}) && name.size() == 1 &&
            name[0] >= 'x' && name[0] <= 'z') {
            xyz_[name[0] - 'x'] = number(name);
            have_ |= 1 << (name[0] - 'x');
        } else if (at({"amf", "object", "mesh", "vertices"}) && name == "vertex") {
            if (have_ != 7) fail("<vertex> lacks " + std::string(have_ & 1 ? have_ & 2 ? "<z>" : "<y>" : "<x>"));
            out_.parts.back().points.emplace_back(xyz_[0], xyz_[1], xyz_[2]);
        } else if (at({"amf", "object", "mesh", "volume", "triangle"}) && name.size() == 2 && name[0] == 'v' &&
                   name[1] >= '1' && name[1] <= '3') {
            const double v = number(name);
            const std::size_t n = out_.parts.back().points.size();
            if (v < 0 || v != std::floor(v)) fail("<" + name + "> is not a vertex index: '" + trimmed() + "'");
            if (v >= static_cast<double>(n))
                fail("<triangle> refers to vertex " + trimmed() + " (the object has " + std::to_string(n) + ")");
            tri_[name[1] - '1'] = static_cast<std::uint32_t>(v);
            have_ |= 1 << (name[1] - '1');
        } else if (at({"amf", "object", "mesh", "volume"}) && name == "triangle") {
            if (have_ != 7) fail("<triangle> lacks " + std::string(have_ & 1 ? have_ & 2 ? "<v3>" : "<v2>" : "<v1>"));
            if (++faces_ > how_.max_faces)
                throw MeshLimitError("line " + std::to_string(line()) + ": more than " +
                                     std::to_string(how_.max_faces) + " triangles (--max-list)");
            out_.parts.back().faces.push_back({tri_[0], tri_[1], tri_[2]});
        }
        text_.clear();
    }

    ImportedMesh finish() {
        for (const auto& [name, at] : ignored_)
            out_.warnings.push_back("line " + std::to_string(at) + ": " +
                                    (name == "edge" ? "<edge>: curved triangles are read flat, as OpenSCAD 2021.01 reads them"
                                                    : "<constellation> is not placed: each object is taken once where "
                                                      "it is stored, as OpenSCAD 2021.01 takes it"));
        const double mm = unit_mm(unit_);
        if (how_.openscad) {
            if (mm != 1)
                out_.warnings.push_back("unit=\"" + unit_ + "\" is ignored (read as millimetres), as OpenSCAD 2021.01 "
                                        "ignores it");
        } else if (mm == 0) {
            throw MeshFormatError("unknown unit=\"" + unit_ + "\" (AMF's are millimeter, inch, feet, meter, micron)");
        } else if (mm != 1) {
            for (auto& p : out_.parts)
                for (glm::dvec3& q : p.points) q *= mm;
        }
        std::erase_if(out_.parts, [](const graph::PolygonMesh& p) { return p.faces.empty(); });
        return std::move(out_);
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw MeshFormatError("line " + std::to_string(line()) + ": " + message);
    }

private:
    bool at(std::initializer_list<const char*> names) const {
        if (names.size() != path_.size()) return false;
        std::size_t i = 0;
        for (const char* n : names)
            if (path_[i++] != n) return false;
        return true;
    }
    // The line of the element being read (the parser's own line runs ahead).
    int line() const {
        const xmlNode* n = xmlTextReaderCurrentNode(r_);
        return n ? static_cast<int>(xmlGetLineNo(n)) : xmlTextReaderGetParserLineNumber(r_);
    }
    std::string attribute(const char* name) const {
        xmlChar* v = xmlTextReaderGetAttribute(r_, reinterpret_cast<const xmlChar*>(name));
        std::string s = v ? reinterpret_cast<const char*>(v) : "";
        xmlFree(v);
        return s;
    }
    std::string trimmed() const {
        const std::size_t a = text_.find_first_not_of(" \t\r\n");
        if (a == std::string::npos) return "";
        return text_.substr(a, text_.find_last_not_of(" \t\r\n") + 1 - a);
    }
    double number(const std::string& element) const {
        double v = 0;
        if (!parse_number(trimmed(), v)) fail("<" + element + "> is not a number: '" + trimmed().substr(0, 40) + "'");
        return v;
    }

    xmlTextReaderPtr r_;
    const MeshReading& how_;
    ImportedMesh out_;
    std::vector<std::string> path_;  // open elements, the root first
    std::string text_, unit_;
    double xyz_[3] = {0, 0, 0};
    std::uint32_t tri_[3] = {0, 0, 0};
    int have_ = 0;  // bits: which of x, y, z (or v1, v2, v3) were given
    std::uint64_t faces_ = 0;
    std::map<std::string, int> ignored_;  // element → first line
};

}  // namespace

ImportedMesh module_read_amf(const std::string& bytes, const MeshReading& how) {
    // No network, no external entities or DTDs: only the file's own bytes.
    std::unique_ptr<xmlTextReader, void (*)(xmlTextReaderPtr)> reader(
        xmlReaderForMemory(bytes.data(), static_cast<int>(bytes.size()), nullptr, nullptr,
                           XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING),
        xmlFreeTextReader);
    if (!reader) throw MeshFormatError("not a readable AMF file");
    std::string first_fatal;
    xmlTextReaderSetStructuredErrorHandler(reader.get(), keep_first_fatal, &first_fatal);
    AmfReader amf(reader.get(), how);
    for (;;) {
        const int got = xmlTextReaderRead(reader.get());
        if (got == 0) break;
        if (got < 0) throw MeshFormatError("not a readable AMF file" + (first_fatal.empty() ? "" : ": " + first_fatal));
        const int type = xmlTextReaderNodeType(reader.get());
        if (type == XML_READER_TYPE_ELEMENT) {
            amf.start(reinterpret_cast<const char*>(xmlTextReaderConstLocalName(reader.get())),
                      xmlTextReaderIsEmptyElement(reader.get()) == 1);
        } else if (type == XML_READER_TYPE_END_ELEMENT) {
            amf.end();
        } else if (type == XML_READER_TYPE_TEXT || type == XML_READER_TYPE_CDATA) {
            const xmlChar* v = xmlTextReaderConstValue(reader.get());
            if (v) amf.text(reinterpret_cast<const char*>(v));
        }
    }
    if (!first_fatal.empty()) throw MeshFormatError("not a readable AMF file: " + first_fatal);
    return amf.finish();
}

}  // namespace kerf::eval::mesh_format

// import() of OFF, AMF and 3MF files (docs/language.md, "Meshes from
// files"): the unit cube in each encoding measured against its closed form;
// AMF and 3MF units, 3MF build transforms and components placed as the
// formats define (.sdl) and as OpenSCAD 2021.01 reads them (.scad, with
// warnings); broken files are located errors in .sdl and warnings that make
// nothing in .scad. The 3MF packages are zipped here from their XML text.
#include <catch2/catch.hpp>

#include <algorithm>

#include <zip.h>

#include "tests/interpreter/import/mesh_files.hpp"

using kerf::test::TempTree;
using namespace kerf::test::mesh_files;

namespace {

std::string n(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", x);
    return b;
}

// "line N" of the first `needle` in `text` (where an error must point).
std::string line_of(const std::string& text, const std::string& needle, std::size_t from = 0) {
    const std::size_t at = text.find(needle, from);
    REQUIRE(at != std::string::npos);
    return "line " + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

// The cube as OFF: quads, comments, a colour after each vertex and face (COFF).
std::string off_cube() {
    std::string s = "COFF # with colours\n\n# counts\n8 6 12\n";
    for (const auto& c : kCorners) s += n(c.x) + " " + n(c.y) + " " + n(c.z) + " 0.5 0.5 0.5 1 # a corner\n";
    for (const auto& q : kQuads)
        s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
             std::to_string(q[3]) + " 255 0 0\n";
    return s;
}

// The cube's triangles as AMF <triangle>s (or 3MF's attributes).
std::string amf_object(int id, glm::dvec3 at = glm::dvec3(0)) {
    std::string s = "<object id=\"" + std::to_string(id) + "\"><metadata type=\"name\">c</metadata><mesh><vertices>\n";
    for (const auto& c : kCorners)
        s += "<vertex><coordinates><x>" + n(c.x + at.x) + "</x><y>" + n(c.y + at.y) + "</y><z>" + n(c.z + at.z) +
             "</z></coordinates></vertex>\n";
    s += "</vertices>\n";
    int k = 0;
    for (const auto& q : kQuads) {  // two volumes: their triangles together make the object's mesh
        if (k++ % 3 == 0) s += k == 1 ? "<volume materialid=\"1\">\n" : "</volume><volume>\n";
        s += "<triangle><v1>" + std::to_string(q[0]) + "</v1><v2>" + std::to_string(q[1]) + "</v2><v3>" +
             std::to_string(q[2]) + "</v3></triangle><triangle><v1>" + std::to_string(q[0]) + "</v1><v2>" +
             std::to_string(q[2]) + "</v2><v3>" + std::to_string(q[3]) + "</v3></triangle>\n";
    }
    return s + "</volume></mesh></object>\n";
}

std::string amf(const std::string& body, const std::string& unit = "") {
    return "<?xml version=\"1.0\"?>\n<amf" + (unit.empty() ? "" : " unit=\"" + unit + "\"") + ">\n" +
           "<material id=\"1\"><color><r>1</r><g>0</g><b>0</b></color></material>\n" + body + "</amf>\n";
}

std::string mesh_3mf(int id) {
    std::string s = "<object id=\"" + std::to_string(id) + "\" type=\"model\"><mesh><vertices>";
    for (const auto& c : kCorners) s += "<vertex x=\"" + n(c.x) + "\" y=\"" + n(c.y) + "\" z=\"" + n(c.z) + "\"/>";
    s += "</vertices><triangles>";
    for (const auto& q : kQuads)
        s += "<triangle v1=\"" + std::to_string(q[0]) + "\" v2=\"" + std::to_string(q[1]) + "\" v3=\"" +
             std::to_string(q[2]) + "\"/><triangle v1=\"" + std::to_string(q[0]) + "\" v2=\"" + std::to_string(q[2]) +
             "\" v3=\"" + std::to_string(q[3]) + "\"/>";
    return s + "</triangles></mesh></object>";
}

// A zip archive of `entries` (name, text).
void write_zip(TempTree& t, const std::string& name, const std::vector<std::pair<std::string, std::string>>& entries) {
    int err = 0;
    zip_t* z = zip_open(t.path(name).c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
    REQUIRE(z);
    for (const auto& [entry, text] : entries) {
        zip_source_t* src = zip_source_buffer(z, text.data(), text.size(), 0);
        REQUIRE(zip_file_add(z, entry.c_str(), src, ZIP_FL_OVERWRITE) >= 0);
    }
    REQUIRE(zip_close(z) == 0);
}

// A 3MF package (a zip of the model and the two parts that point at it).
void write_3mf(TempTree& t, const std::string& name, const std::string& resources, const std::string& build,
               const std::string& unit = "") {
    const std::string model =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model xmlns=\"http://schemas.microsoft.com/3dmanufacturing/"
        "core/2015/02\"" + (unit.empty() ? "" : " unit=\"" + unit + "\"") + "><resources>" + resources +
        "</resources><build>" + build + "</build></model>";
    const std::string types =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/"
        "content-types\"><Default Extension=\"rels\" ContentType=\"application/vnd.openxmlformats-package."
        "relationships+xml\"/><Default Extension=\"model\" ContentType=\"application/vnd.ms-package.3dmanufacturing-"
        "3dmodel+xml\"/></Types>";
    const std::string rels =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships xmlns=\"http://schemas.openxmlformats.org/package/"
        "2006/relationships\"><Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" Type=\"http://schemas.microsoft."
        "com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>";
    write_zip(t, name, {{"[Content_Types].xml", types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model}});
}

// The parts an import made (its meshes, in order) and its warnings.
struct Imported {
    std::vector<Measures> parts;
    std::vector<std::string> warnings;
};

Imported import_of(TempTree& t, const std::string& name, const char* dialect = "sdl") {
    Imported r;
    const kerf::EvalResult e = eval_file(t.write(std::string("s.") + dialect, "import(\"" + name + "\");\n"));
    for (const auto& m : e.graph.meshes) r.parts.push_back(measure(m));
    for (const auto& d : e.warnings) r.warnings.push_back(d.message);
    return r;
}

}  // namespace

TEST_CASE("OFF, AMF and 3MF cubes import as the closed unit cube", "[import]") {
    TempTree t;
    t.write("cube.off", off_cube());
    t.write("cube.amf", amf(amf_object(0)));
    write_3mf(t, "cube.3mf", mesh_3mf(1), "<item objectid=\"1\"/>");
    for (const char* name : {"cube.off", "cube.amf", "cube.3mf"}) {
        for (const char* dialect : {"sdl", "scad"}) {
            INFO(name << " in ." << dialect);
            const Imported r = import_of(t, name, dialect);
            CHECK(r.warnings.empty());
            REQUIRE(r.parts.size() == 1);
            CHECK(r.parts[0].volume == Approx(-1.0));  // clockwise from outside, like polyhedron()
            CHECK(r.parts[0].area == Approx(6.0));
            CHECK(r.parts[0].lo == glm::dvec3(0));
            CHECK(r.parts[0].hi == glm::dvec3(1));
        }
    }
}

TEST_CASE("AMF objects are parts to unite, units scale in .sdl and are ignored in .scad, as OpenSCAD does",
          "[import]") {
    TempTree t;
    t.write("two.amf", amf(amf_object(0) + amf_object(1, {0.5, 0, 0})));
    CHECK(import_of(t, "two.amf").parts.size() == 2);
    t.write("inch.amf", amf(amf_object(0), "inch"));
    Imported r = import_of(t, "inch.amf");
    REQUIRE(r.parts.size() == 1);
    CHECK(r.parts[0].volume == Approx(-25.4 * 25.4 * 25.4));
    CHECK(r.parts[0].hi == glm::dvec3(25.4));
    CHECK(r.warnings.empty());
    r = import_of(t, "inch.amf", "scad");
    CHECK(r.parts[0].volume == Approx(-1.0));
    REQUIRE(r.warnings.size() == 1);
    CHECK(r.warnings[0] ==
          "import: \"inch.amf\": unit=\"inch\" is ignored (read as millimetres), as OpenSCAD 2021.01 ignores it");
    // Compressed: the entry named like the file, or the only one, as OpenSCAD looks for it.
    write_zip(t, "zipped.amf", {{"zipped.amf", amf(amf_object(0), "inch")}, {"notes.txt", "not the model"}});
    CHECK(import_of(t, "zipped.amf").parts.at(0).volume == Approx(-25.4 * 25.4 * 25.4));
    write_zip(t, "one.amf", {{"model.xml", amf(amf_object(0))}});
    CHECK(import_of(t, "one.amf").parts.at(0).volume == Approx(-1.0));
    write_zip(t, "two.amf", {{"a.amf", amf(amf_object(0))}, {"b.amf", amf(amf_object(0))}});
    CHECK(error_in(t.write("s.sdl", "import(\"two.amf\");\n")) ==
          "1:1: error: import(\"two.amf\"): a compressed AMF file must hold one file or one named 'two.amf', this "
          "one holds 2");
    t.write("m.amf", amf(amf_object(0), "meter"));
    CHECK(import_of(t, "m.amf").parts[0].volume == Approx(-1e9));
    // Curved triangles and constellations are read as OpenSCAD reads them, with a warning.
    std::string curved = amf(amf_object(0) + "<constellation id=\"9\"><instance objectid=\"0\"><deltax>5</deltax>"
                                             "</instance></constellation>\n");
    curved.insert(curved.find("</vertices>"), "<edge><v1>0</v1><dx1>0</dx1><dy1>1</dy1><dz1>0</dz1><v2>1</v2>"
                                              "<dx2>0</dx2><dy2>1</dy2><dz2>0</dz2></edge>\n");
    t.write("curved.amf", curved);
    r = import_of(t, "curved.amf");
    CHECK(r.parts.size() == 1);
    REQUIRE(r.warnings.size() == 2);
    CHECK(r.warnings[0] == "import: \"curved.amf\" " + line_of(curved, "<constellation") +
                               ": <constellation> is not placed: each object is taken once where it is stored, as "
                               "OpenSCAD 2021.01 takes it");
    CHECK(r.warnings[1] == "import: \"curved.amf\" " + line_of(curved, "<edge>") +
                               ": <edge>: curved triangles are read flat, as OpenSCAD 2021.01 reads them");
}

TEST_CASE("3MF build items, transforms, components and units in .sdl, OpenSCAD's reading in .scad", "[import]") {
    TempTree t;
    write_3mf(t, "placed.3mf", mesh_3mf(1),
              "<item objectid=\"1\" transform=\"2 0 0 0 2 0 0 0 2 10 0 0\"/>"
              "<item objectid=\"1\" transform=\"-1 0 0 0 1 0 0 0 1 0 0 0\"/>",
              "centimeter");
    Imported r = import_of(t, "placed.3mf");
    REQUIRE(r.parts.size() == 2);
    CHECK(r.parts[0].volume == Approx(-8000.0));  // doubled, in cm: 20 mm
    CHECK(r.parts[0].lo == glm::dvec3(100, 0, 0));
    CHECK(r.parts[0].hi == glm::dvec3(120, 20, 20));
    CHECK(r.parts[1].volume == Approx(-1000.0));  // mirrored, and still outward
    CHECK(r.parts[1].lo == glm::dvec3(-10, 0, 0));
    CHECK(r.warnings.empty());
    r = import_of(t, "placed.3mf", "scad");
    REQUIRE(r.parts.size() == 1);
    CHECK(r.parts[0].hi == glm::dvec3(1));
    REQUIRE(r.warnings.size() == 2);
    CHECK(r.warnings[0] == "import: \"placed.3mf\": unit=\"centimeter\" is ignored (read as millimetres), as "
                           "OpenSCAD 2021.01 ignores it");
    CHECK(r.warnings[1] == "import: \"placed.3mf\": the build (2 item(s), their transforms and components) is not "
                           "applied: each of the 1 mesh object(s) is taken once where it is stored, as OpenSCAD "
                           "2021.01 takes it");
    write_3mf(t, "comp.3mf",
              mesh_3mf(1) + "<object id=\"2\" type=\"model\"><components><component objectid=\"1\" "
                            "transform=\"1 0 0 0 1 0 0 0 1 0 5 0\"/><component objectid=\"1\"/></components></object>",
              "<item objectid=\"2\" transform=\"1 0 0 0 1 0 0 0 1 0 0 3\"/>");
    r = import_of(t, "comp.3mf");
    REQUIRE(r.parts.size() == 2);
    CHECK(r.parts[0].lo == glm::dvec3(0, 5, 3));
    CHECK(r.parts[1].lo == glm::dvec3(0, 0, 3));
}

TEST_CASE("broken OFF, AMF and 3MF files: located errors in .sdl, a warning and nothing in .scad",
          "[import][errors]") {
    TempTree t;
    const std::string off = off_cube();
    CHECK(err_of(t, "cut.off", off.substr(0, off.find("4 0 3 2 1"))) ==
          "import(\"cut.off\"): line 13: expected a face, got the end of the file");
    std::string bad = off;
    bad.replace(bad.find("4 4 5 6 7"), 9, "4 4 5 6 8");
    CHECK(err_of(t, "range.off", bad) == "import(\"range.off\"): line 14: face 1 refers to vertex 8 (there are 8)");
    CHECK(err_of(t, "nan.off", "OFF\n3 1 0\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
          "import(\"nan.off\"): a vertex is not finite");
    CHECK(err_of(t, "two.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1 # two corners\n") ==
          "import(\"two.off\"): line 6: a face needs at least 3 corners, got 2");
    CHECK(err_of(t, "none.off", "OFF\n0 0 0\n") == "import(\"none.off\"): the file holds no faces");
    CHECK(err_of(t, "head.off", "PLY\n") ==
          "import(\"head.off\"): line 1: not an OFF file: expected the header 'OFF', got 'PLY'");
    CHECK(err_of(t, "lying.off", "OFF\n1000000 1 0\n0 0 0\n") ==
          "import(\"lying.off\"): the file declares 1000000 vertices but only 6 bytes follow (truncated?)");
    CHECK(err_of(t, "bin.off", "OFF BINARY\n") ==
          "import(\"bin.off\"): line 1: binary OFF is not read (only the text form)");
    const std::string cube = amf(amf_object(0));
    const std::string cut = cube.substr(0, cube.find("<z>", cube.find("<vertex>", cube.find("<vertex>") + 1)));
    // (libxml2's streaming reader words a truncated document so.)
    CHECK(err_of(t, "cut.amf", cut) == "import(\"cut.amf\"): not a readable AMF file: " +
                                        line_of(cut, "</y>", cut.rfind("<x>")) +
                                        ": Extra content at the end of the document");
    std::string range = cube;
    range.replace(range.find("<v3>7</v3>"), 10, "<v3>9</v3>");
    CHECK(err_of(t, "range.amf", range) == "import(\"range.amf\"): " + line_of(range, "<v3>9</v3>") +
                                            ": <triangle> refers to vertex 9 (the object has 8)");
    std::string word = cube;
    word.replace(word.find("<x>1</x>"), 8, "<x>one</x>");
    CHECK(err_of(t, "word.amf", word) ==
          "import(\"word.amf\"): " + line_of(word, "<x>one") + ": <x> is not a number: 'one'");
    CHECK(err_of(t, "root.amf", "<svg/>") ==
          "import(\"root.amf\"): line 1: not an AMF file: the root element is <svg>, not <amf>");
    CHECK(err_of(t, "furlong.amf", amf(amf_object(0), "furlong")) ==
          "import(\"furlong.amf\"): unknown unit=\"furlong\" (AMF's are millimeter, inch, feet, meter, micron)");
    t.write("junk.3mf", "not a zip");
    CHECK(err_of(t, "junk.3mf", "not a zip") ==
          "import(\"junk.3mf\"): not a readable 3MF file: reading: Could not read ZIP file");
    std::string tri = mesh_3mf(1);
    tri.replace(tri.find("v3=\"7\""), 6, "v3=\"9\"");
    write_3mf(t, "range.3mf", tri, "<item objectid=\"1\"/>");
    CHECK(error_in(t.write("s.sdl", "import(\"range.3mf\");\n")) ==
          "1:1: error: import(\"range.3mf\"): not a readable 3MF file: reading: Invalid model node index");
    write_3mf(t, "empty.3mf", mesh_3mf(1), "");
    CHECK(error_in(t.write("s.sdl", "import(\"empty.3mf\");\n")) ==
          "1:1: error: import(\"empty.3mf\"): the 3MF build has no items: nothing to make");

    // .scad: OpenSCAD prints a warning (or a CGAL message, or aborts) and
    // imports nothing; kerf warns at the import and makes nothing.
    t.write("range.off", bad);
    Imported r = import_of(t, "range.off", "scad");
    CHECK(r.parts.empty());
    REQUIRE(r.warnings.size() == 1);
    CHECK(r.warnings[0] == "import: \"range.off\": line 14: face 1 refers to vertex 8 (there are 8): nothing is made, "
                           "as OpenSCAD imports nothing from a file it cannot read");
    r = import_of(t, "range.3mf", "scad");
    CHECK(r.parts.empty());
    CHECK(r.warnings.size() == 1);
    // A bound stays an error in both dialects; a missing file is one in .sdl
    // (a .scad file warns and makes nothing, as OpenSCAD:
    // tests/scripts/openscad/missing_files.scad).
    kerf::EvalOptions opt;
    opt.limits.list_elements = 5;
    t.write("cube.amf", cube);
    std::size_t sixth = 0;
    for (int i = 0; i < 6; ++i) sixth = cube.find("<triangle>", sixth + 1);
    CHECK(error_in(t.write("s.scad", "import(\"cube.amf\");\n"), opt) ==
          "1:1: error: import(\"cube.amf\"): " + line_of(cube, "<triangle>", sixth) + ": more than 5 triangles (--max-list)");
    CHECK(error_in(t.write("s.sdl", "import(\"missing.off\");\n")) == "1:1: error: cannot find 'missing.off'");
}

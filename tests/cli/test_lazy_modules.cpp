// kerf's optional modules load only when a run needs them (csg/modules.hpp,
// docs/performance.md "Start-up"): the dynamic loader's own record of every
// file it loads (LD_DEBUG=files) of a real run says which libraries a plain
// PNG render brings in, and that importing a compressed AMF or drawing
// text() brings in the zip or the font module and its libraries and still
// reads the file or draws the text.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <string>

#include "tests/cli/measure_scene.hpp"

namespace {

// The libraries of the optional modules: each costs milliseconds at start.
const char* kLazy[] = {"libkerf_zip.so",   "libkerf_view.so",  "libkerf_codecs.so", "libkerf_oiio.so",
                       "libkerf_fonts.so", "lib3MF.so",        "libzip.so",         "libcrypto.so",
                       "libssl.so",        "libcpp-httplib.so", "libOpenImageIO.so", "libharfbuzz.so",
                       "libfontconfig.so", "libfreetype.so",   "libglib-2.0.so",    "libkerf_xml.so",
                       "libxml2.so",       "libicuuc.so"};

const char* kScene = "camera(position = [3, 3, 2], look_at = [0, 0, 0]);\nlight(position = [5, -5, 10]);\n";

// A 16×16 render of `scene` with the loader's record of every file loaded
// on stderr.
KerfRun traced_render(const std::filesystem::path& dir, const std::string& scene) {
    return run_kerf("render '" + scene + "' -o '" + (dir / "t.png").string() + "' -W 16 -H 16 --no-progress", dir,
                    "LD_DEBUG=files ");
}

}  // namespace

TEST_CASE("a PNG render loads none of the optional modules' libraries", "[modules]") {
    const auto dir = test_dir("lazy_modules_png");
    const std::string scene = write_file(dir / "tiny.sdl", std::string(kScene) + "sphere(1);\n");
    const KerfRun r = traced_render(dir, scene);
    REQUIRE(r.status == 0);
    CHECK(r.err.find("file=libembree3.so") != std::string::npos);  // the record lists what is loaded
    for (const char* lib : kLazy) {
        INFO(lib);
        CHECK(r.err.find(lib) == std::string::npos);
    }
}

TEST_CASE("a compressed AMF import loads the zip and XML modules and reads the file", "[modules][import]") {
    const auto dir = test_dir("lazy_modules_amf");
    write_file(dir / "plain.amf",
               "<?xml version=\"1.0\"?>\n<amf><object id=\"0\"><mesh><vertices>"
               "<vertex><coordinates><x>0</x><y>0</y><z>0</z></coordinates></vertex>"
               "<vertex><coordinates><x>1</x><y>0</y><z>0</z></coordinates></vertex>"
               "<vertex><coordinates><x>0</x><y>1</y><z>0</z></coordinates></vertex>"
               "<vertex><coordinates><x>0</x><y>0</y><z>1</z></coordinates></vertex>"
               "</vertices><volume><triangle><v1>0</v1><v2>2</v2><v3>1</v3></triangle>"
               "<triangle><v1>0</v1><v2>1</v2><v3>3</v3></triangle><triangle><v1>0</v1><v2>3</v2><v3>2</v3></triangle>"
               "<triangle><v1>1</v1><v2>2</v2><v3>3</v3></triangle></volume></mesh></object></amf>\n");
    REQUIRE(std::system(("cd '" + dir.string() +
                         "' && python3 -c \"import zipfile; zipfile.ZipFile('tet.amf', 'w', zipfile.ZIP_DEFLATED)"
                         ".write('plain.amf', 'tet.amf')\"")
                            .c_str()) == 0);
    const std::string scene = write_file(dir / "tet.sdl", std::string(kScene) + "import(\"tet.amf\");\n");
    const KerfRun r = traced_render(dir, scene);
    INFO(r.err.substr(r.err.size() > 2000 ? r.err.size() - 2000 : 0));
    REQUIRE(r.status == 0);
    CHECK(r.err.find("libkerf_zip.so") != std::string::npos);
    CHECK(r.err.find("file=libzip.so") != std::string::npos);
    CHECK(r.err.find("libkerf_xml.so") != std::string::npos);  // the unzipped XML
    CHECK(r.err.find("file=libxml2.so") != std::string::npos);
    CHECK(r.err.find("libcpp-httplib.so") == std::string::npos);  // kerf view's module stays out
    // The unit tetrahedron's volume, 1/6: the module read the right bytes.
    const Measured m = measure_file(dir, "import(\"tet.amf\");", "measure.sdl");
    REQUIRE(m.status == 0);
    CHECK(m.volume == Approx(1.0 / 6).epsilon(2e-3));
}

TEST_CASE("text() loads the font module and draws the glyphs", "[modules][text]") {
    const auto dir = test_dir("lazy_modules_text");
    const std::string scene = write_file(dir / "text.sdl", std::string(kScene) + "linear_extrude(1) text(\"I\", size = 10);\n");
    const KerfRun r = traced_render(dir, scene);
    REQUIRE(r.status == 0);
    CHECK(r.err.find("libkerf_fonts.so") != std::string::npos);
    CHECK(r.err.find("file=libharfbuzz.so") != std::string::npos);
    CHECK(r.err.find("libkerf_zip.so") == std::string::npos);  // the zip module stays out
    // An "I" is a bar: its volume is positive and well under its box's
    // (size 10: about 1.4 × 7.3 × 1 in Liberation Sans), so the module drew it.
    const Measured m = measure_file(dir, "linear_extrude(1) text(\"I\", size = 10);", "measure.sdl");
    REQUIRE(m.status == 0);
    CHECK(m.volume > 5);
    CHECK(m.volume < 15);
    if (const double ref = openscad_volume(dir, "linear_extrude(1) text(\"I\", size = 10);"); std::isfinite(ref))
        CHECK(m.volume == Approx(ref).epsilon(1e-3));
}

// `use <f.ttf>` makes a font file's families known to text(), as OpenSCAD
// registers a used font file (docs/language.md, "Text"). Run under a
// fontconfig configuration that knows no font at all, so only the file the
// script names can make the family found.
#include <catch2/catch.hpp>

#include "tests/cli/run_kerf.hpp"

namespace fs = std::filesystem;

TEST_CASE("use of a font file makes its family usable by text()", "[text]") {
    const fs::path font = "/usr/share/fonts/truetype/liberation2/LiberationSerif-Regular.ttf";
    if (!fs::exists(font)) {
        WARN("skipped: fonts-liberation2 is not installed");
        return;
    }
    auto dir = test_dir("font_use");
    write_file(dir / "fonts.conf", "<?xml version=\"1.0\"?>\n<fontconfig><cachedir>" + (dir / "cache").string() +
                                       "</cachedir></fontconfig>\n");
    const std::string env = "FONTCONFIG_FILE='" + (dir / "fonts.conf").string() + "' ";
    fs::copy_file(font, dir / "serif.ttf");
    fs::copy_file(font, dir / "serif.TTF");
    const std::string text = "text(\"Hi\", font = \"Liberation Serif\");\n";
    auto check = [&](const std::string& name, const std::string& script) {
        return run_kerf("check '" + write_file(dir / name, script) + "'", dir, env);
    };

    // Without the use, no font is known: the family is not found.
    auto r = check("bare.sdl", text);
    CHECK(r.status == 1);
    CHECK(r.err.find("bare.sdl:1:1: error: text: no font found for 'Liberation Serif'") != std::string::npos);

    r = check("used.sdl", "use <serif.ttf>\n" + text);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    r = check("upper.scad", "use <serif.TTF>\n" + text);  // the extension in any case, as OpenSCAD
    CHECK(r.status == 0);

    // A file that is not a font: an error in .sdl, OpenSCAD's warning in .scad.
    write_file(dir / "junk.ttf", "not a font\n");
    r = check("junk.sdl", "use <junk.ttf>\ncube(1);\n");
    CHECK(r.status == 1);
    CHECK(r.err.find("junk.sdl:1:1: error: cannot read the font file 'junk.ttf'") != std::string::npos);
    r = check("junk.scad", "use <junk.ttf>\ncube(1);\n");
    CHECK(r.status == 0);
    CHECK(r.err.find("junk.scad:1:1: warning: Can't read font with path 'junk.ttf'") != std::string::npos);
}

// Fonts for text() (docs/language.md, "Text"): a font named the way
// OpenSCAD names it ("Liberation Sans:style=Bold", a fontconfig pattern),
// found through fontconfig and opened with FreeType once per run and file,
// in the font module (font_module/font_module.hpp) that fonts.cpp opens on
// the first call; without the module these throw FontError naming it.
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>

typedef struct FT_FaceRec_* FT_Face;

namespace kerf::text {

// A font that is not installed, or a file FreeType cannot read: the
// message says which and what to do.
class FontError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A font name fontconfig cannot parse (`":charset=xxx"`).
class FontNameError : public FontError {
public:
    using FontError::FontError;
};

struct Font {
    FT_Face face = nullptr;  // owned by the font cache, valid for the process
    std::string family;      // as the font file names itself
    std::string file;
};

// The default font when text() names none: Liberation Sans from Debian's
// fonts-liberation2 package, opened by its path first so that a machine with
// other fonts installed (or the older fonts-liberation) renders the same.
inline constexpr std::string_view kDefaultFont = "Liberation Sans";

// The font for `spec` (empty = the default). Throws FontError when
// fontconfig's best match is not of the family asked for (fontconfig always
// offers some font; a silent substitute would be a silently wrong model),
// unless `fallback` is set (the OpenSCAD dialect): then the substitute is
// returned and `substituted` names it. A pattern that names no family
// (`":style=Bold"`) is Liberation Sans in that style, or with `fallback`
// fontconfig's own best match, as OpenSCAD 2021.01 takes it. An
// unparseable name throws FontNameError.
Font find_font(std::string_view spec, bool fallback, std::string* substituted);

// `use <f.ttf>` (or .otf): the font file's families join the fonts
// find_font knows, for the rest of the process, as OpenSCAD registers
// them. False when fontconfig cannot read the file.
bool register_font_file(const std::string& path);

}  // namespace kerf::text

// fontconfig lookup and the FreeType face cache behind find_font, in the
// font module (font_module.hpp).
#include "interpreter/text/font.hpp"
#include "interpreter/text/font_module/font_module.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <mutex>
#include <sys/stat.h>

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

namespace kerf::text {

namespace {

constexpr const char* kDefaultFile = "/usr/share/fonts/truetype/liberation2/LiberationSans-Regular.ttf";

struct Cache {
    std::mutex mutex;
    FT_Library library = nullptr;
    std::map<std::pair<std::string, int>, FT_Face> faces;  // faces live for the process
};

Cache& cache() {
    static Cache c;
    return c;
}

bool same_name(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

Font open_face(const std::string& file, int index) {
    Cache& c = cache();
    std::lock_guard lock(c.mutex);
    if (!c.library && FT_Init_FreeType(&c.library) != 0) throw FontError("FreeType could not start");
    FT_Face& face = c.faces[{file, index}];
    if (!face && FT_New_Face(c.library, file.c_str(), index, &face) != 0) {
        face = nullptr;
        throw FontError("cannot read the font file '" + file + "'");
    }
    if (!FT_IS_SCALABLE(face)) throw FontError("the font file '" + file + "' has no outlines (a bitmap font)");
    return Font{face, face->family_name ? face->family_name : "", file};
}

using Pattern = std::unique_ptr<FcPattern, decltype(&FcPatternDestroy)>;

}  // namespace

bool fontconfig_ready() {
    static std::once_flag init;
    static bool fc_ok = false;
    std::call_once(init, [] { fc_ok = FcInit() == FcTrue; });
    return fc_ok;
}

bool module_register_font_file(const std::string& path) {
    return fontconfig_ready() && FcConfigAppFontAddFile(nullptr, reinterpret_cast<const FcChar8*>(path.c_str())) == FcTrue;
}

Font module_find_font(std::string_view spec, bool fallback, std::string* substituted) {
    struct stat st {};
    if (spec.empty() && ::stat(kDefaultFile, &st) == 0) return open_face(kDefaultFile, 0);
    const std::string name(spec.empty() ? kDefaultFont : spec);
    if (!fontconfig_ready()) throw FontError("fontconfig could not start, so no font can be found");
    Pattern pattern(FcNameParse(reinterpret_cast<const FcChar8*>(name.c_str())), FcPatternDestroy);
    if (!pattern)
        throw FontNameError("'" + name + "' is not a font name (expected 'Family' or 'Family:style=Style')");
    FcChar8* asked = nullptr;
    std::string family = FcPatternGetString(pattern.get(), FC_FAMILY, 0, &asked) == FcResultMatch
                             ? reinterpret_cast<const char*>(asked)
                             : std::string(kDefaultFont);
    // No family: OpenSCAD leaves the choice to fontconfig (`":style=Bold"`
    // draws DejaVu Sans Bold where that is fontconfig's sans-serif,
    // measured); kerf's own dialect keeps its default family, the same on
    // every machine.
    const bool any_family = !asked && fallback;
    if (!asked && !fallback)
        FcPatternAddString(pattern.get(), FC_FAMILY, reinterpret_cast<const FcChar8*>(kDefaultFont.data()));
    FcConfigSubstitute(nullptr, pattern.get(), FcMatchPattern);
    FcDefaultSubstitute(pattern.get());
    FcResult result = FcResultNoMatch;
    Pattern match(FcFontMatch(nullptr, pattern.get(), &result), FcPatternDestroy);
    FcChar8* file = nullptr;
    if (!match || FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch)
        throw FontError("no font found for '" + name + "' (is fontconfig configured? fc-list lists the fonts)");
    int index = 0;
    FcPatternGetInteger(match.get(), FC_INDEX, 0, &index);
    bool same = any_family;
    FcChar8* got = nullptr;
    for (int i = 0; FcPatternGetString(match.get(), FC_FAMILY, i, &got) == FcResultMatch; ++i)
        same = same || same_name(family, reinterpret_cast<const char*>(got));
    if (!same) {
        std::string hint = spec.empty() ? " (install Debian's fonts-liberation2)" : " (fc-list lists the installed fonts)";
        if (!fallback || spec.empty()) throw FontError("font '" + family + "' is not installed" + hint);
        // The default font, not fontconfig's best guess, so
        // that the substitute is the same on every machine.
        if (substituted) *substituted = std::string(kDefaultFont);
        return module_find_font("", false, nullptr);
    }
    return open_face(reinterpret_cast<const char*>(file), index);
}

}  // namespace kerf::text

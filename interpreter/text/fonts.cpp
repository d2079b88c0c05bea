// find_font, register_font_file and layout_text through the font module
// (font_module/font_module.hpp), opened on the first call, so that kerf
// starts without fontconfig, FreeType, HarfBuzz and the libraries they
// bring (docs/performance.md, "Start-up").
#include <stdexcept>
#include <string>

#include "csg/modules.hpp"
#include "interpreter/text/font_module/font_module.hpp"

namespace kerf::text {

namespace {

struct FontModule {
    LayoutEntry layout = nullptr;
    FindEntry find = nullptr;
    RegisterEntry add = nullptr;
};

FontModule load_font_module() {
    std::string why;
    if (void* h = csg::open_module(KERF_FONTS_MODULE_NAME, KERF_FONTS_MODULE_PATH, &why)) {
        why.clear();
        const FontModule m{csg::module_entry<LayoutEntry>(h, "kerf_fonts_layout", &why),
                           csg::module_entry<FindEntry>(h, "kerf_fonts_find", &why),
                           csg::module_entry<RegisterEntry>(h, "kerf_fonts_register", &why)};
        if (why.empty()) return m;
    }
    throw FontError(csg::module_error("font", KERF_FONTS_MODULE_NAME, why));
}

// The module, loaded once (a failed load throws and is tried again on the next call).
const FontModule& font_module() {
    static const FontModule m = load_font_module();
    return m;
}

// The module's answer as the exception its reader threw.
void rethrow(int status, const std::string& error) {
    switch (status) {
        case kFontOk: return;
        case kFontNameError: throw FontNameError(error);
        case kFontError: throw FontError(error);
        default: throw std::invalid_argument(error);
    }
}

}  // namespace

Font find_font(std::string_view spec, bool fallback, std::string* substituted) {
    Font out;
    std::string error;
    rethrow(font_module().find(spec, fallback, substituted, out, error), error);
    return out;
}

bool register_font_file(const std::string& path) {
    // Without the module no font can be read: the caller's located "cannot
    // read the font file" is the error (text() itself names the module).
    try {
        return font_module().add(path);
    } catch (const FontError&) {
        return false;
    }
}

TextShape layout_text(const TextParams& params) {
    TextShape out;
    std::string error;
    rethrow(font_module().layout(params, out, error), error);
    return out;
}

}  // namespace kerf::text

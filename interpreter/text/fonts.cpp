// find_font, register_font_file and layout_text through the font module
// (font_module/font_module.hpp), opened on the first call, so that kerf
// starts without fontconfig, FreeType, HarfBuzz and the libraries they
// bring (docs/performance.md, "Start-up").
#include <dlfcn.h>

#include <mutex>
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

// The module, loaded once; a failed load is tried again on the next call.
const FontModule& font_module() {
    static std::mutex mutex;
    static FontModule m;
    std::lock_guard<std::mutex> lock(mutex);
    if (m.layout) return m;
    std::string why;
    if (void* h = csg::open_module(KERF_FONTS_MODULE_NAME, KERF_FONTS_MODULE_PATH, &why)) {
        FontModule got;
        got.layout = reinterpret_cast<LayoutEntry>(::dlsym(h, "kerf_fonts_layout"));
        got.find = reinterpret_cast<FindEntry>(::dlsym(h, "kerf_fonts_find"));
        got.add = reinterpret_cast<RegisterEntry>(::dlsym(h, "kerf_fonts_register"));
        if (got.layout && got.find && got.add) return m = got;
        why = "it lacks kerf_fonts_layout";
    }
    throw FontError(csg::module_error("font", KERF_FONTS_MODULE_NAME, why));
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

// The font module's entry points (font_module.hpp): the readers'
// exceptions turned into a status and a message.
#include <exception>
#include <stdexcept>
#include <string>

#include "interpreter/text/font_module/font_module.hpp"

namespace {

using namespace kerf::text;

template <class F>
int answer(std::string& error, F read) {
    try {
        read();
        return kFontOk;
    } catch (const FontNameError& e) {
        error = e.what();
        return kFontNameError;
    } catch (const FontError& e) {
        error = e.what();
        return kFontError;
    } catch (const std::exception& e) {
        error = e.what();
        return kFontBadArgument;
    }
}

}  // namespace

#define KERF_EXPORT extern "C" __attribute__((visibility("default")))

KERF_EXPORT int kerf_fonts_layout(const TextParams& params, TextShape& out, std::string& error) {
    return answer(error, [&] { out = module_layout_text(params); });
}

KERF_EXPORT int kerf_fonts_find(std::string_view spec, bool fallback, std::string* substituted, Font& out,
                                std::string& error) {
    return answer(error, [&] { out = module_find_font(spec, fallback, substituted); });
}

KERF_EXPORT bool kerf_fonts_register(const std::string& path) { return module_register_font_file(path); }

// The font module, libkerf_fonts.so: fontconfig, FreeType and HarfBuzz
// (with GLib, Graphite and Expat behind them, 8 libraries) for text() and
// `use <font.ttf>`. They cost ~1 ms of every kerf start when kerf linked
// them; as a module they load on the first text() or font file
// (docs/performance.md, "Start-up"). fonts.cpp loads it.
//
// The entry points are C functions (found by dlsym) on C++ data: the
// module is built with kerf, from the same headers, by the same compiler.
// Each catches what it throws and answers with a code and a message, so no
// exception crosses the module's boundary; the module's other symbols are
// hidden, so its readers never bind to kerf's forwarding functions.
#pragma once
#include <string>
#include <string_view>

#include "interpreter/text/font.hpp"
#include "interpreter/text/layout.hpp"

namespace kerf::text {

// What an entry point answers: the exception its reader threw.
enum FontStatus : int { kFontOk = 0, kFontError = 1, kFontNameError = 2, kFontBadArgument = 3 };

// kerf_fonts_layout: layout_text.
using LayoutEntry = int (*)(const TextParams& params, TextShape& out, std::string& error);
// kerf_fonts_find: find_font.
using FindEntry = int (*)(std::string_view spec, bool fallback, std::string* substituted, Font& out,
                          std::string& error);
// kerf_fonts_register: register_font_file.
using RegisterEntry = bool (*)(const std::string& path);

// The module's own readers (font.cpp, layout.cpp), throwing as font.hpp and
// layout.hpp say.
Font module_find_font(std::string_view spec, bool fallback, std::string* substituted);
bool module_register_font_file(const std::string& path);
TextShape module_layout_text(const TextParams& params);

}  // namespace kerf::text

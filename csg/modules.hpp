// kerf's optional modules: shared objects opened with dlopen on first use,
// so that a run which needs none of them loads none of their libraries —
// the image codecs and OpenImageIO (render/image/), the zip-based imports
// (interpreter/import/zip_module/), the XML-based ones (xml_module/), the
// fonts (interpreter/text/font_module/) and kerf view's HTTP server (cli/view/).
// Each costs milliseconds to load, OpenImageIO half a second
// (docs/performance.md, "Image formats" and "Start-up").
#pragma once
#include <string>

namespace kerf::csg {

// Opens the module `name` beside the running executable (an installed
// kerf), else at `built` (where the build put it, for the build tree and
// the tests). Returns the handle, or nullptr with `*why` saying why: the
// loader's message, or that it is in neither place.
void* open_module(const char* name, const char* built, std::string* why);

// `symbol` in the module `handle` as a function pointer of type F, or
// nullptr with `*why` (if still empty) saying "it lacks SYMBOL". Callers
// load a module into a function-local static initialised by a loader that
// throws on failure: the static stays unset and the next call tries again.
void* module_symbol(void* handle, const char* symbol);
template <class F>
F module_entry(void* handle, const char* symbol, std::string* why) {
    F f = reinterpret_cast<F>(module_symbol(handle, symbol));
    if (!f && why->empty()) *why = std::string("it lacks ") + symbol;
    return f;
}

// The message for a module that cannot be loaded: "cannot load the WHAT
// module NAME: WHY", for the caller's own error type.
std::string module_error(const char* what, const char* name, const std::string& why);

}  // namespace kerf::csg

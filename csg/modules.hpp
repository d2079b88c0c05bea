// kerf's optional modules: shared objects opened with dlopen on first use,
// so that a run which needs none of them loads none of their libraries —
// the image codecs and OpenImageIO (render/image/), the zip-based imports
// (interpreter/import/zip_module/) and kerf view's HTTP server (cli/view/).
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

// The message for a module that cannot be loaded: "cannot load the WHAT
// module NAME: WHY", for the caller's own error type.
std::string module_error(const char* what, const char* name, const std::string& why);

}  // namespace kerf::csg

// libpng's error handling for the PNG writer and reader: libpng calls the
// error function and expects it not to return, so it longjmps back to the
// setjmp of the call that started the work, with the message kept.
#pragma once
#include <csetjmp>
#include <cstdio>

#include <png.h>

namespace kerf::render {

// Passed to libpng as the error pointer (as PngJump*, also by structs
// derived from it).
struct PngJump {
    std::jmp_buf jump;
    char message[256] = "";
};

inline void png_jump_error(png_structp png, png_const_charp msg) {
    auto* j = static_cast<PngJump*>(png_get_error_ptr(png));
    std::snprintf(j->message, sizeof j->message, "%s", msg);
    std::longjmp(j->jump, 1);
}

inline void png_no_warning(png_structp, png_const_charp) {}

}  // namespace kerf::render

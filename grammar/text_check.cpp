#include "grammar/text_check.hpp"

namespace kerf::grammar {

std::size_t find_invalid_byte(std::string_view text) {
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        const unsigned char c = s[i];
        if (c < 0x80) {
            if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F) return i;
            ++i;
            continue;
        }
        // Lead byte: number of continuation bytes and the allowed range of
        // the first one (which rules out overlong forms and surrogates).
        std::size_t len = 0;
        unsigned char lo = 0x80, hi = 0xBF;
        if (c >= 0xC2 && c <= 0xDF) len = 1;
        else if (c == 0xE0) len = 2, lo = 0xA0;
        else if (c >= 0xE1 && c <= 0xEC) len = 2;
        else if (c == 0xED) len = 2, hi = 0x9F;
        else if (c >= 0xEE && c <= 0xEF) len = 2;
        else if (c == 0xF0) len = 3, lo = 0x90;
        else if (c >= 0xF1 && c <= 0xF3) len = 3;
        else if (c == 0xF4) len = 3, hi = 0x8F;
        else return i;
        if (i + len >= n) return i;  // truncated sequence
        if (s[i + 1] < lo || s[i + 1] > hi) return i;
        for (std::size_t k = 2; k <= len; ++k)
            if (s[i + k] < 0x80 || s[i + k] > 0xBF) return i;
        i += len + 1;
    }
    return std::string_view::npos;
}

}  // namespace kerf::grammar

// The little JSON kerf view's events need: strings escaped, numbers in the
// shortest form that reads back as the same double.
#pragma once
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

namespace kerf::view {

inline std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '"' || c == '\\') out += '\\', out += char(c);
        else if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else if (c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else out += char(c);
    }
    return out + "\"";
}

// Shortest round-trip decimal; JSON has no inf or NaN (null then).
inline std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : "null";
}

}  // namespace kerf::view

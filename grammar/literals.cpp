#include "grammar/literals.hpp"

#include <cstdint>
#include <string>

#include <charconv>
#include <limits>

namespace kerf::grammar {

namespace {
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_hex(std::string_view t) {
    for (char c : t)
        if (!is_digit(c) && !((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'))) return false;
    return true;
}

// Length of the numeric part: digits, optional fraction, optional exponent.
std::size_t numeric_length(std::string_view t) {
    std::size_t i = 0;
    while (i < t.size() && is_digit(t[i])) ++i;
    if (i < t.size() && t[i] == '.') {
        ++i;
        while (i < t.size() && is_digit(t[i])) ++i;
    }
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        std::size_t j = i + 1;
        if (j < t.size() && (t[j] == '+' || t[j] == '-')) ++j;
        if (j < t.size() && is_digit(t[j])) {
            while (j < t.size() && is_digit(t[j])) ++j;
            i = j;
        }
    }
    return i;
}

// For a literal from_chars calls out of range: does it overflow (true) or
// underflow (false)? Decided from the position of the first significant
// digit relative to the decimal point, plus the exponent.
bool overflows(std::string_view t) {
    long long magnitude = 0;  // decimal exponent of the first significant digit, +1
    std::size_t i = 0;
    bool seen = false;
    long long int_digits = 0, leading_frac_zeros = 0;
    for (; i < t.size() && is_digit(t[i]); ++i)
        if (seen || t[i] != '0') {
            seen = true;
            ++int_digits;
        }
    if (i < t.size() && t[i] == '.')
        for (++i; i < t.size() && is_digit(t[i]); ++i) {
            if (seen) continue;
            if (t[i] == '0') ++leading_frac_zeros;
            else seen = true;
        }
    magnitude = int_digits > 0 ? int_digits : -leading_frac_zeros;
    long long exp = 0;
    bool neg = false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
        ++i;
        if (i < t.size() && (t[i] == '+' || t[i] == '-')) neg = t[i++] == '-';
        for (; i < t.size() && is_digit(t[i]); ++i)
            if (exp < 1'000'000'000) exp = exp * 10 + (t[i] - '0');
    }
    return magnitude + (neg ? -exp : exp) > 0;
}
}  // namespace

std::optional<double> parse_number(std::string_view text) {
    if (numeric_length(text) != text.size()) return std::nullopt;
    double value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc::result_out_of_range)
        return overflows(text) ? std::numeric_limits<double>::infinity() : 0.0;
    if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    return value;
}

void append_utf8(std::string& out, std::uint32_t c) {
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

std::string decode_string(std::string_view literal) {
    std::string out;
    if (literal.size() < 2) return out;
    std::string_view body = literal.substr(1, literal.size() - 2);
    out.reserve(body.size());
    for (std::size_t i = 0; i < body.size(); ++i) {
        char c = body[i];
        if (c == '\\' && i + 1 < body.size()) {
            const char e = body[i + 1];
            const std::size_t n = e == 'x' ? 2 : e == 'u' ? 4 : e == 'U' ? 6 : 0;
            if (n && i + 2 + n <= body.size() && is_hex(body.substr(i + 2, n)) && (e != 'x' || body[i + 2] <= '7')) {
                const auto code = static_cast<std::uint32_t>(std::stoul(std::string(body.substr(i + 2, n)), nullptr, 16));
                // OpenSCAD 2021 (measured): code 0, a surrogate or a code
                // past U+10FFFF is a space.
                const bool bad = code == 0 || (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF;
                append_utf8(out, bad ? ' ' : code);
                i += 1 + n;
                continue;
            }
            switch (body[++i]) {
                case 'n': c = '\n'; break;
                case 't': c = '\t'; break;
                case 'r': c = '\r'; break;
                default: c = body[i]; break;  // \" and \\; in .scad any other (the grammar rejects it in .sdl)
            }
        }
        out += c;
    }
    return out;
}

}  // namespace kerf::grammar

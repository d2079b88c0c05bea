#include "grammar/source.hpp"

#include <algorithm>

#include "grammar/text_check.hpp"

namespace kerf {

namespace {

// Diagnostics go to a terminal whatever the script holds: a 1 MB identifier,
// binary garbage or a newline inside a message must not flood it, garble it
// or break the one-line form editors parse (docs/spec.md §8). These bounds keep a
// diagnostic a few hundred bytes whatever the input.
constexpr std::size_t kMaxWord = 64;       // longer names are shown as their start + "..."
constexpr std::size_t kWordKept = 40;
constexpr std::size_t kMaxMessage = 400;   // longer messages keep head + "..." + tail
constexpr std::size_t kMessageHead = 300;
constexpr std::size_t kMessageTail = 80;
constexpr std::size_t kLineWindow = 100;   // source bytes shown on each side of the caret

std::string_view line_of(const std::string& text, std::uint32_t line) {
    std::size_t pos = 0;
    for (std::uint32_t l = 1; l < line; ++l) {
        pos = text.find('\n', pos);
        if (pos == std::string::npos) return {};
        ++pos;
    }
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view v(text.data() + pos, end - pos);
    if (!v.empty() && v.back() == '\r') v.remove_suffix(1);
    return v;
}

bool is_continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// Calls emit(unit_text) for each display unit of s: a valid UTF-8 character,
// or "?" for an invalid byte or a control character (tabs kept when asked,
// so a caret can be aligned under them).
template <class Emit>
void for_each_unit(std::string_view s, bool keep_tabs, Emit emit) {
    for (std::size_t i = 0; i < s.size();) {
        const std::size_t n = grammar::utf8_sequence_length(s, i);
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (n == 0 || ((c < 0x20 || c == 0x7F) && !(keep_tabs && c == '\t'))) {
            emit(std::string_view(c == '\n' ? "\\n" : "?"));
            i += 1;
        } else {
            emit(s.substr(i, n));
            i += n;
        }
    }
}

std::string printable(std::string_view s, bool keep_tabs) {
    std::string out;
    for_each_unit(s, keep_tabs, [&](std::string_view u) { out += u; });
    return out;
}

// Never cut inside a UTF-8 character: move a cut position forward to the
// next character start.
std::size_t char_boundary(std::string_view s, std::size_t pos) {
    while (pos < s.size() && is_continuation(static_cast<unsigned char>(s[pos]))) ++pos;
    return pos;
}

bool is_word_byte(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '$';
}

// Messages quote user text (names, values, strings): shorten very long
// names, then the whole message if it is still long.
std::string clipped_message(const std::string& message) {
    std::string words;
    for (std::size_t i = 0; i < message.size();) {
        std::size_t j = i;
        while (j < message.size() && is_word_byte(message[j])) ++j;
        if (j == i) {
            words += message[i++];
        } else {
            std::string_view word(message.data() + i, j - i);
            words += word.size() > kMaxWord ? std::string(word.substr(0, kWordKept)) + "..." : std::string(word);
            i = j;
        }
    }
    std::string text = printable(words, false);
    if (text.size() <= kMaxMessage) return text;
    std::string_view v(text);
    const std::size_t head = char_boundary(v, kMessageHead);
    const std::size_t tail = char_boundary(v, v.size() - kMessageTail);
    return std::string(v.substr(0, head)) + " ... " + std::string(v.substr(tail));
}

// The source line around the 0-based byte column `col`, with "..." where it
// was clipped, and the caret line under it (one column per character).
std::string source_and_caret(std::string_view src, std::size_t col) {
    if (col > src.size()) col = src.size();
    const std::size_t start = col > kLineWindow ? std::min(col, char_boundary(src, col - kLineWindow)) : 0;
    const std::size_t end = char_boundary(src, std::min(src.size(), col + kLineWindow));
    std::string line = start > 0 ? "..." : "";
    std::string caret = start > 0 ? "   " : "";
    const std::size_t caret_at = std::max(start, col);
    for_each_unit(src.substr(start, caret_at - start), true,
                  [&](std::string_view u) { caret += u == "\t" ? '\t' : ' '; });
    line += printable(src.substr(start, end - start), true);
    if (end < src.size()) line += "...";
    return line + '\n' + caret + '^';
}

}  // namespace

std::string format_diagnostic_head(const Diagnostic& d) {
    std::string out = d.loc.file ? printable(d.loc.file->path, false) : std::string("<command line>");
    if (d.loc.line > 0) {
        out += ':' + std::to_string(d.loc.line) + ':' + std::to_string(d.loc.col);
    }
    out += d.severity == Severity::Error ? ": error: " : d.severity == Severity::Warning ? ": warning: " : ": note: ";
    out += clipped_message(d.message);
    if (d.repeats > 1) out += " (" + std::to_string(d.repeats) + " times)";
    return out;
}

std::string format_diagnostic(const Diagnostic& d) {
    std::string out = format_diagnostic_head(d);
    if (d.loc.file && d.loc.line > 0) {
        std::string_view src = line_of(d.loc.file->text, d.loc.line);
        out += '\n' + source_and_caret(src, d.loc.col > 0 ? d.loc.col - 1 : 0);
    }
    for (const Diagnostic& n : d.notes) out += '\n' + format_diagnostic(n);
    return out;
}

}  // namespace kerf

#include "grammar/source.hpp"

namespace kerf {

namespace {
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
}  // namespace

std::string format_diagnostic_head(const Diagnostic& d) {
    std::string out = d.loc.file ? d.loc.file->path : std::string("<command line>");
    if (d.loc.line > 0) {
        out += ':' + std::to_string(d.loc.line) + ':' + std::to_string(d.loc.col);
    }
    out += d.severity == Severity::Error ? ": error: " : ": warning: ";
    out += d.message;
    return out;
}

std::string format_diagnostic(const Diagnostic& d) {
    std::string out = format_diagnostic_head(d);
    if (!d.loc.file || d.loc.line == 0) return out;
    std::string_view src = line_of(d.loc.file->text, d.loc.line);
    // Long or binary lines would make the caret display useless: clip them.
    constexpr std::size_t max_shown = 200;
    std::size_t col = d.loc.col > 0 ? d.loc.col - 1 : 0;
    std::size_t start = col > max_shown / 2 ? col - max_shown / 2 : 0;
    if (start > src.size()) start = src.size();
    std::string_view shown = src.substr(start, max_shown);
    std::string line;
    for (char c : shown) line += (static_cast<unsigned char>(c) < 0x20 && c != '\t') ? '?' : c;
    out += '\n';
    out += line;
    out += '\n';
    for (std::size_t i = start; i < col && i - start < shown.size(); ++i)
        out += (src[i] == '\t') ? '\t' : ' ';
    out += '^';
    return out;
}

}  // namespace kerf

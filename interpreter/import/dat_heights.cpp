// surface()'s .dat files, read line by line as OpenSCAD 2021.01 does:
// each line trimmed, blank and '#' lines skipped, the rest split at spaces
// and tabs into numbers, the first token that is not one ending the reading.
#include <cmath>
#include <string_view>

#include "interpreter/import/formats.hpp"
#include "interpreter/import/height_map.hpp"
#include "interpreter/import/mesh_import.hpp"

namespace kerf::eval {

namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

}  // namespace

DatHeights read_dat(const std::string& path, std::uint64_t max_heights) {
    const mesh_format::MeshFile file(path);
    const std::string text = file.read_all();
    DatHeights out;
    std::uint64_t count = 0;
    std::size_t line_no = 0;
    for (std::size_t at = 0; at < text.size() && !out.stop;) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        const std::string_view line = trimmed(std::string_view(text).substr(at, end - at));
        at = end + 1;
        ++line_no;
        if (line.empty() || line.front() == '#') continue;
        std::vector<double> row;
        for (std::size_t i = 0; i < line.size();) {
            if (line[i] == ' ' || line[i] == '\t') {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
            const std::string_view token = line.substr(i, j - i);
            i = j;
            double v = 0;
            if (!mesh_format::parse_number(token, v)) {
                out.stop = DatHeights::Stop{line_no, std::string(token)};
                break;
            }
            if (!std::isfinite(v))
                throw MeshFormatError("line " + std::to_string(line_no) + ": height '" + std::string(token) +
                                      "' is not finite");
            if (++count > max_heights)
                throw MeshFormatError("more than " + std::to_string(max_heights) + " heights (--max-list)");
            row.push_back(v);
        }
        if (row.empty()) continue;  // a line stopped at its first token adds no row
        out.rows.push_back(std::move(row));
        out.lines.push_back(line_no);
    }
    return out;
}

}  // namespace kerf::eval

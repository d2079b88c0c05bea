// DIMENSION entities read as group-code pairs (dxflib splits dimensions by
// kind and drops the raw defining points OpenSCAD's formulas use), and the
// formulas of OpenSCAD 2021.01's dxf_dim()/dxf_cross().
#include "interpreter/import/dxf_dims.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>

#include "interpreter/import/mesh_import.hpp"

namespace kerf::eval {

namespace {

std::string trim(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

double number(const std::string& v, std::uint64_t line) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x))
        throw MeshFormatError("not a readable DXF file: line " + std::to_string(line) + " is not a finite number");
    return x;
}

}  // namespace

std::vector<DxfDimension> read_dxf_dimensions(const std::string& path, glm::dvec2 origin, double scale) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw MeshFormatError("cannot open the file");
    std::vector<DxfDimension> out;
    std::string code_line, value;
    std::string section, entity, last;
    bool want_name = false;
    DxfDimension d;
    for (std::uint64_t n = 1; std::getline(in, code_line); n += 2) {
        const std::string c = trim(code_line);
        char* end = nullptr;
        const long code = std::strtol(c.c_str(), &end, 10);
        if (c.empty() || *end != '\0')
            throw MeshFormatError("not a readable DXF file: line " + std::to_string(n) + " is not a group code");
        if (!std::getline(in, value)) break;
        value = trim(value);
        if (code == 0) {
            if (entity == "DIMENSION") out.push_back(d);
            entity = section == "ENTITIES" ? value : "";
            d = DxfDimension{};
            if (value == "SECTION") want_name = true;
            if (value == "ENDSEC") section.clear();
            if (value == "EOF") break;
            continue;
        }
        if (want_name && code == 2) section = value, want_name = false;
        if (entity != "DIMENSION") continue;
        if (code == 8) d.layer = value;
        else if (code == 1) d.name = value;
        else if (code == 70) d.type = int(number(value, n + 1));
        else if (code == 50) d.angle = number(value, n + 1);
        else if (code >= 10 && code <= 16) d.points[code - 10].x = (number(value, n + 1) - origin.x) * scale;
        else if (code >= 20 && code <= 26) d.points[code - 20].y = (number(value, n + 1) - origin.y) * scale;
    }
    return out;
}

std::optional<double> dimension_value(const DxfDimension& d) {
    const glm::dvec2* p = d.points;
    switch (d.type & 7) {
    case 0: {  // rotated, horizontal or vertical
        const glm::dvec2 v = p[4] - p[3];
        const double a = d.angle * std::numbers::pi / 180;
        return std::abs(v.x * std::cos(a) + v.y * std::sin(a));
    }
    case 1: return glm::length(p[4] - p[3]);  // aligned
    case 2: {  // angular; OpenSCAD's atan2(x, y), kept so its angles come out
        const double a1 = std::atan2(p[0].x - p[5].x, p[0].y - p[5].y);
        const double a2 = std::atan2(p[4].x - p[3].x, p[4].y - p[3].y);
        return std::abs(a1 - a2) * 180 / std::numbers::pi;
    }
    case 3:
    case 4: return glm::length(p[5] - p[0]);  // diameter, radius
    case 6: return (d.type & 64) ? p[3].x : p[3].y;  // ordinate
    default: return std::nullopt;                     // angular by three points
    }
}

std::optional<glm::dvec2> line_cross(glm::dvec2 a0, glm::dvec2 a1, glm::dvec2 b0, glm::dvec2 b1) {
    const double dem = (b1.y - b0.y) * (a1.x - a0.x) - (b1.x - b0.x) * (a1.y - a0.y);
    if (dem == 0) return std::nullopt;
    const double ua = ((b1.x - b0.x) * (a0.y - b0.y) - (b1.y - b0.y) * (a0.x - b0.x)) / dem;
    return a0 + ua * (a1 - a0);
}

}  // namespace kerf::eval

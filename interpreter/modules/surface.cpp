// surface(file, center, invert, convexity): a height map as the closed mesh
// OpenSCAD 2021.01 builds (docs/language.md "Height maps"): each grid cell
// four triangles around its centre at the mean of its corners, walls down
// to a flat base at min(0, lowest height − 1), the base one polygon.
#include <algorithm>
#include <strings.h>

#include "interpreter/import/height_map.hpp"
#include "interpreter/import/mesh_import.hpp"
#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

namespace {

enum { File, Center, Invert, Convexity };

// heights[i][j] at (j, i) before centring; a missing height (a short .dat
// row) is 0 but does not lower the base, as in OpenSCAD.
struct Grid {
    std::vector<std::vector<double>> heights;
    std::size_t columns = 0;
    double base = 0;
};

bool is_png(const std::string& path) {
    return path.size() >= 4 && strcasecmp(path.c_str() + path.size() - 4, ".png") == 0;
}

[[noreturn]] void file_error(ModuleCall& c, const std::string& message) {
    throw SourceError(c.st.loc, "surface(\"" + c.args[File].as_string() + "\"): " + message);
}

Grid read_grid(ModuleCall& c, const std::string& path, bool invert) {
    const std::string name = "\"" + c.args[File].as_string() + "\"";
    Grid g;
    if (is_png(path)) {
        PngLuminance png = read_png_luminance(path, c.limits().list_elements);
        g.columns = std::size_t(png.width);
        g.heights.resize(std::size_t(png.height));
        for (std::size_t i = 0; i < g.heights.size(); ++i) {
            const double* row = png.rows.data() + (g.heights.size() - 1 - i) * g.columns;  // the bottom row at y = 0
            for (std::size_t j = 0; j < g.columns; ++j)
                g.heights[i].push_back(100.0 / 255 * (invert ? 1 - row[j] : row[j]));  // OpenSCAD's invert, as it is
        }
    } else {
        if (invert) c.warn("invert applies to PNG images only: ignored for " + name);
        DatHeights dat = read_dat(path, c.limits().list_elements);
        if (dat.stop) {
            const std::string what = "line " + std::to_string(dat.stop->line) + ": '" + dat.stop->token + "' is not a number";
            if (!c.lenient()) file_error(c, what);
            c.warn(name + " " + what + ": the heights end there, as OpenSCAD reads them");
        }
        std::size_t widest = 0;
        for (std::size_t i = 0; i < dat.rows.size(); ++i)
            if (dat.rows[i].size() > dat.rows[widest].size()) widest = i;
        for (std::size_t i = 0; i < dat.rows.size(); ++i) {
            if (dat.rows[i].size() == dat.rows[widest].size()) continue;
            const std::string what = "line " + std::to_string(dat.lines[i]) + " has " +
                                     std::to_string(dat.rows[i].size()) + " heights, line " +
                                     std::to_string(dat.lines[widest]) + " has " +
                                     std::to_string(dat.rows[widest].size());
            if (!c.lenient()) file_error(c, what + " (every row needs as many)");
            c.warn(name + " " + what + ": the missing heights are 0, as OpenSCAD takes them");
            break;
        }
        g.columns = dat.rows.empty() ? 0 : dat.rows[widest].size();
        g.heights = std::move(dat.rows);
    }
    for (const auto& row : g.heights)
        for (double v : row) g.base = std::min(g.base, v - 1);
    for (auto& row : g.heights) row.resize(g.columns, 0.0);
    return g;
}

// The mesh in graph::PolygonMesh's order (clockwise seen from outside).
graph::PolygonMesh build_mesh(const Grid& g, bool center) {
    const std::size_t rows = g.heights.size(), cols = g.columns;
    const double ox = center ? -(double(cols) - 1) / 2 : 0, oy = center ? -(double(rows) - 1) / 2 : 0;
    graph::PolygonMesh m;
    auto add = [&](double x, double y, double z) {
        m.points.emplace_back(x, y, z);
        return std::uint32_t(m.points.size() - 1);
    };
    std::vector<std::uint32_t> top(rows * cols), base(rows * cols);
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < cols; ++j) top[i * cols + j] = add(ox + double(j), oy + double(i), g.heights[i][j]);
    // The base's corners: the rim only, shared with the top where a height
    // lies on the base (a missing one), so every edge has two faces.
    for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t j = 0; j < cols; ++j)
            if (i == 0 || j == 0 || i + 1 == rows || j + 1 == cols)
                base[i * cols + j] = g.heights[i][j] == g.base ? top[i * cols + j]
                                                                : add(ox + double(j), oy + double(i), g.base);
    auto T = [&](std::size_t i, std::size_t j) { return top[i * cols + j]; };
    auto B = [&](std::size_t i, std::size_t j) { return base[i * cols + j]; };
    for (std::size_t i = 1; i < rows; ++i)
        for (std::size_t j = 1; j < cols; ++j) {
            const double v1 = g.heights[i - 1][j - 1], v2 = g.heights[i - 1][j], v3 = g.heights[i][j - 1],
                         v4 = g.heights[i][j];
            const std::uint32_t c = add(ox + double(j) - 0.5, oy + double(i) - 0.5, (v1 + v2 + v3 + v4) / 4);
            m.faces.push_back({c, T(i - 1, j), T(i - 1, j - 1)});
            m.faces.push_back({c, T(i, j), T(i - 1, j)});
            m.faces.push_back({c, T(i, j - 1), T(i, j)});
            m.faces.push_back({c, T(i - 1, j - 1), T(i, j - 1)});
        }
    // A wall quad loses a corner where its height lies on the base, and the
    // whole quad where both do.
    auto wall = [&](std::initializer_list<std::uint32_t> corners) {
        std::vector<std::uint32_t> f;
        for (std::uint32_t k : corners)
            if (f.empty() || f.back() != k) f.push_back(k);
        if (f.size() > 1 && f.front() == f.back()) f.pop_back();
        if (f.size() >= 3) m.faces.push_back(std::move(f));
    };
    const std::size_t r = rows - 1, e = cols - 1;
    for (std::size_t i = 1; i < rows; ++i) {
        wall({B(i, 0), T(i, 0), T(i - 1, 0), B(i - 1, 0)});
        wall({B(i - 1, e), T(i - 1, e), T(i, e), B(i, e)});
    }
    for (std::size_t j = 1; j < cols; ++j) {
        wall({B(0, j - 1), T(0, j - 1), T(0, j), B(0, j)});
        wall({B(r, j), T(r, j), T(r, j - 1), B(r, j - 1)});
    }
    // The base counter-clockwise seen from above: clockwise from below.
    std::vector<std::uint32_t> rim;
    for (std::size_t j = 0; j < e; ++j) rim.push_back(B(0, j));
    for (std::size_t i = 0; i < r; ++i) rim.push_back(B(i, e));
    for (std::size_t j = e; j > 0; --j) rim.push_back(B(r, j));
    for (std::size_t i = r; i > 0; --i) rim.push_back(B(i, 0));
    m.faces.push_back(std::move(rim));
    return m;
}

void surface(ModuleCall& c) {
    const Args& a = c.args;
    if (!a.has(File) || !a[File].is_string())
        arg_error(a, "file must be a string naming a .dat height map or a .png image");
    const bool center = arg_bool(a, Center, "center", false);
    const bool invert = arg_bool(a, Invert, "invert", false);
    const std::string path = c.files().resolve_data(a[File].as_string(), c.st.loc);
    const std::string key = std::string("surface|") + (center ? "1" : "0") + (invert ? "1|" : "0|") + path;
    auto it = c.state().imported.find(key);
    if (it == c.state().imported.end()) {
        Grid g;
        try {
            g = read_grid(c, path, invert);
        } catch (const MeshFormatError& e) {
            file_error(c, e.what());
        }
        const std::size_t rows = g.heights.size(), cols = g.columns;
        if (rows < 2 || cols < 2)
            arg_error(a, "\"" + a[File].as_string() + "\" has " + std::to_string(rows) +
                             (rows == 1 ? " row" : " rows") + " of " + std::to_string(cols) +
                             " heights: a height map needs 2 rows of 2 to enclose anything");
        const std::uint64_t faces = 4 * std::uint64_t(rows - 1) * (cols - 1) + 2 * (rows - 1) + 2 * (cols - 1) + 1;
        if (faces > c.limits().list_elements)
            file_error(c, std::to_string(rows) + " x " + std::to_string(cols) + " heights make " +
                              std::to_string(faces) + " faces, more than the limit " +
                              std::to_string(c.limits().list_elements) + " (--max-list)");
        it = c.state().imported.emplace(key, c.add_mesh(build_mesh(g, center))).first;
    }
    c.add_primitive(csg::PrimKind::Mesh, {}, it->second);
}

// convexity is OpenSCAD's preview hint: accepted, nothing to do (the
// tracer is exact).
const ModuleEntry kSurface[] = {
    {"surface", ModuleKind::Solid, {"file", "center", "invert", "convexity"}, surface},
};

}  // namespace

std::span<const ModuleEntry> surface_modules() { return kSurface; }

}  // namespace kerf::eval

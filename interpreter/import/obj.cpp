// Wavefront OBJ: 'v x y z' vertices and 'f a b c ...' polygons whose corners
// are 'i', 'i/t', 'i//n' or 'i/t/n' with 1-based or negative (relative)
// indices. Everything else (normals, texture coordinates, groups, materials,
// lines) does not define the solid and is skipped.
#include "interpreter/import/mesh_import.hpp"
#include "interpreter/import/formats.hpp"

namespace kerf::eval::mesh_format {

graph::PolygonMesh read_obj(std::string_view bytes, std::uint64_t max_faces) {
    graph::PolygonMesh m;
    Lines lines(bytes);
    while (std::optional<Tokens> line = lines.next()) {
        Tokens& in = *line;
        std::string_view key = in.next();
        if (key == "v") {
            double x = in.number("a vertex coordinate");
            double y = in.number("a vertex coordinate");
            double z = in.number("a vertex coordinate");
            m.points.emplace_back(x, y, z);  // an optional w or colour may follow: not part of the position
        } else if (key == "f") {
            if (m.faces.size() >= max_faces) in.fail_limit("more than " + std::to_string(max_faces) + " faces (--max-list)");
            std::vector<std::uint32_t> face;
            for (std::string_view c = in.next(); !c.empty(); c = in.next()) {
                double idx = 0;
                if (!parse_number(c.substr(0, c.find('/')), idx) || idx != static_cast<long long>(idx) || idx == 0)
                    in.fail("expected a vertex index (1-based, or negative from the end), got '" +
                            std::string(c.substr(0, 40)) + "'");
                const double n = static_cast<double>(m.points.size());
                const double abs = idx > 0 ? idx - 1 : n + idx;  // -1 is the last vertex defined so far
                if (abs < 0 || abs >= n)
                    in.fail("vertex index " + std::string(c.substr(0, c.find('/'))) + " refers to no vertex (" +
                            std::to_string(m.points.size()) + " defined so far)");
                face.push_back(static_cast<std::uint32_t>(abs));
            }
            if (face.size() < 3) in.fail("a face needs at least 3 corners, got " + std::to_string(face.size()));
            m.faces.push_back(std::move(face));
        }
    }
    return m;
}

}  // namespace kerf::eval::mesh_format

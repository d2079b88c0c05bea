// import("file.dxf"): a drawing's outlines as a 2D shape (docs/spec.md §10),
// read with Debian's dxflib. As OpenSCAD 2021.01 does: LINE, ARC, CIRCLE,
// LWPOLYLINE and POLYLINE in model space (not in BLOCKs), optionally of
// one layer; loose segments joined end to end into loops (an open chain
// closed by a straight edge); a point
// p becomes (p − origin) · scale; the loops filled by the even-odd rule.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace kerf::eval {

struct DxfCircle {
    glm::dvec2 centre;
    double r;
};

// A bulge of a closed polyline (the arc from p to q, centre and radius)
// kept exact: the circular segment between chord and arc is the disc cut
// by the chord's half-plane on the arc's side; the loops hold the chord, so
// the drawing is their even-odd region XOR the segment, which is a union
// (hole = false) or a cut (hole = true) because the segment meets no other
// outline.
struct DxfSegment {
    glm::dvec2 centre;
    double r;
    glm::dvec2 p, q;
    glm::dvec2 normal;  // unit, from the chord toward the arc
    double sagitta;
    bool hole;
};

struct DxfShape {
    std::vector<std::vector<glm::dvec2>> loops;  // closed, arcs flattened within the tolerance
    // Whole circles that cross no other outline and hold none inside: kept
    // exact, each with its even-odd depth (how many outlines hold it).
    std::vector<DxfCircle> circles;
    std::vector<int> circle_depth;
    std::vector<DxfSegment> segments;  // exact bulges (the rest flattened into loops)
    std::size_t open_paths = 0;
    std::size_t curves = 0;  // ARCs and CIRCLEs read: OpenSCAD cuts them by $fn, $fa and $fs
    std::vector<std::vector<glm::dvec2>> lone_lines;  // open chains of one segment, in file order (dxf_cross)  // chains that do not close: closed by a straight edge, as OpenSCAD does
};

struct DxfOptions {
    std::string layer;  // empty: every layer
    glm::dvec2 origin{0};
    double scale = 1;
    double tolerance = 1e-3;   // chord sagitta / radius for arcs
    std::uint64_t max_entities = 0;
};

// Throws MeshFormatError (mesh_import.hpp) when the file cannot be read as
// DXF or holds non-finite or too many entities.
DxfShape import_dxf(const std::string& path, const DxfOptions& options);

}  // namespace kerf::eval

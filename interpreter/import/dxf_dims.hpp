// The measurements OpenSCAD 2021.01's dxf_dim() and dxf_cross() read from a
// drawing (docs/language.md, "2D drawings"): the DIMENSION entities with
// their defining points, and the crossing of the first two lone LINEs of a
// layer. Points are mapped (p − origin)·scale as import() maps outlines.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace kerf::eval {

struct DxfDimension {
    std::string layer, name;  // group 8; the dimension's text, group 1
    int type = 0;             // group 70
    double angle = 0;         // group 50, degrees
    glm::dvec2 points[7]{};   // groups 10–16 (x) and 20–26 (y), mapped
};

// The DIMENSION entities of the ENTITIES section. Throws MeshFormatError
// (mesh_import.hpp) for a file that is not one of group-code lines.
std::vector<DxfDimension> read_dxf_dimensions(const std::string& path, glm::dvec2 origin, double scale);

// dxf_dim's value of one dimension, as OpenSCAD computes it per type
// (linear: the points 3→4 projected on the angle; aligned: their distance;
// angular: between the lines 5→0 and 3→4; radius and diameter: 0→5;
// ordinate: point 3's x or y); nothing for the types OpenSCAD does not read.
std::optional<double> dimension_value(const DxfDimension& d);

// Where the lines a0→a1 and b0→b1 cross, nothing when they are parallel.
std::optional<glm::dvec2> line_cross(glm::dvec2 a0, glm::dvec2 a1, glm::dvec2 b0, glm::dvec2 b1);

}  // namespace kerf::eval

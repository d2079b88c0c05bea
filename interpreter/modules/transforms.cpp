// Booleans and transforms (docs/spec.md §4). Matrices are world_from_child and
// compose like OpenSCAD's: the statement's matrix applies to its block.
#include <cmath>

#include "interpreter/degrees.hpp"
#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

namespace {

glm::dmat4 rot_axis(double d, glm::dvec3 u) {
    double c = cos_deg(d), s = sin_deg(d), t = 1 - c;
    glm::dmat4 m(1.0);
    // Row r, column k is m[k][r].
    m[0][0] = c + t * u.x * u.x;       m[1][0] = t * u.x * u.y - s * u.z; m[2][0] = t * u.x * u.z + s * u.y;
    m[0][1] = t * u.x * u.y + s * u.z; m[1][1] = c + t * u.y * u.y;       m[2][1] = t * u.y * u.z - s * u.x;
    m[0][2] = t * u.x * u.z - s * u.y; m[1][2] = t * u.y * u.z + s * u.x; m[2][2] = c + t * u.z * u.z;
    return m;
}

glm::dmat4 rotate_matrix(const Args& a) {
    if (!a.has(0)) return glm::dmat4(1.0);
    const Value& ang = a[0];
    if (ang.is_list()) {
        if (a.has(1)) arg_error(a, "v is only allowed with a single angle");
        const ValueList& l = ang.as_list();
        if (!ang.is_vector() || l.empty() || l.size() > 3)
            arg_error(a, "a must be a number or a vector of up to 3 numbers, got " + to_repr(ang));
        double e[3] = {0, 0, 0};
        for (std::size_t i = 0; i < l.size(); ++i) {
            e[i] = l[i].as_number();
            if (!std::isfinite(e[i])) arg_error(a, "angles must be finite, got " + to_repr(ang));
        }
        return euler_rotation({e[0], e[1], e[2]});
    }
    double deg = arg_number(a, 0, "a", 0);
    if (!a.has(1)) return rot_z(deg);
    glm::dvec3 v = arg_vec3(a, 1, "v", {0, 0, 1});
    double len = glm::length(v);
    if (!(len > 0)) arg_error(a, "axis v must not be zero");
    return rot_axis(deg, v / len);
}

using NK = graph::NodeKind;

// An operation node over the children's solids: union, intersection,
// difference (an empty block still makes the empty solid).
template <NK kind>
void boolean(ModuleCall& c) {
    std::size_t mark = c.graph().mark();
    const std::size_t ghosts = c.state().ghosts.size();
    c.children();
    const std::uint32_t first = c.graph().mark() > mark ? c.graph().pending[mark] : csg::kNone;
    c.graph().make_node(mark, kind, c.st.loc);
    if (kind == NK::Difference) c.state().ghost_minuend(ghosts, first, c.graph().pending.back());
}

// render() and group() are OpenSCAD's: a plain union here.
void plain_union(ModuleCall& c) {
    std::size_t mark = c.graph().mark();
    c.children();
    c.graph().group(mark, c.st.loc);
}

// A transform of 2D shapes uses only its action in the plane, as
// OpenSCAD's does (x, y rows and the x, y translation), so z stays the
// unit slab the shapes are carried on (docs/spec.md §10).
glm::dmat4 planar(const Args& a, const glm::dmat4& m) {
    glm::dmat4 p(1.0);
    p[0][0] = m[0][0]; p[0][1] = m[0][1];
    p[1][0] = m[1][0]; p[1][1] = m[1][1];
    p[3][0] = m[3][0]; p[3][1] = m[3][1];
    if (!(p[0][0] * p[1][1] - p[0][1] * p[1][0] != 0))
        arg_error(a, "the transform flattens the 2D shape to a line (its action in the XY plane is singular)");
    return p;
}

// |det| of the columns scaled to unit length (Hadamard's bound): 0 for a
// map that flattens, 1 for a rotation, whatever the model's size.
double volume_ratio(const glm::dmat3& l) {
    glm::dmat3 u;
    for (int k = 0; k < 3; ++k) {
        if (!(glm::length(l[k]) > 0)) return 0;
        u[k] = glm::normalize(l[k]);
    }
    return std::abs(glm::determinant(u));
}

// OpenSCAD 2021 removes a 2D shape whose transform is singular in the plane
// (with the warning below) and keeps a 3D solid flattened to a sheet of no
// volume, which kerf cannot show: in .scad both make nothing, with a warning.
bool flattened_away(ModuleCall& c, const glm::dmat4& m, bool flat) {
    if (!c.lenient()) return false;
    if (flat && m[0][0] * m[1][1] - m[0][1] * m[1][0] == 0) {
        c.warn("Scaling a 2D object with 0 - removing object");
        return true;
    }
    if (flat || volume_ratio(glm::dmat3(m)) > 1e-12) return false;
    c.warn("the transform flattens its children to no volume: nothing is made (OpenSCAD keeps a flat sheet)");
    return true;
}

// The children under world_from_child `m`; nothing when they make no solid.
void transformed(ModuleCall& c, glm::dmat4 m) {
    GraphBuilder& g = c.graph();
    std::size_t mark = g.mark();
    {
        GhostFrameScope frame(c.state(), m);  // `%` and `#` parts inside are placed by it
        c.children();
    }
    if (g.mark() == mark) return;
    if (flattened_away(c, m, g.flat_since(mark))) return g.pending.resize(mark);
    if (g.flat_since(mark)) m = planar(c.args, m);
    g.add_matrix(m);
    g.wrap(mark, NK::Transform, static_cast<std::uint32_t>(g.graph.matrices.size() - 1), c.st.loc);
}

void translate(ModuleCall& c) {
    glm::dmat4 m(1.0);
    m[3] = glm::dvec4(arg_vec3(c.args, 0, "v", {0, 0, 0}, true), 1.0);
    transformed(c, m);
}

void rotate(ModuleCall& c) { transformed(c, rotate_matrix(c.args)); }

void scale(ModuleCall& c) {
    const Args& a = c.args;
    glm::dvec3 f(1);
    if (a.has(0) && a[0].is_number()) f = glm::dvec3(arg_number(a, 0, "v", 1));
    else f = arg_vec3(a, 0, "v", f, true, 1);
    for (int k = 0; k < 3; ++k)  // .scad: see flattened_away
        if (f[k] == 0 && !c.lenient()) arg_error(a, "factor must not be 0");
    glm::dmat4 m(1.0);
    m[0][0] = f.x;
    m[1][1] = f.y;
    m[2][2] = f.z;
    transformed(c, m);
}

void mirror(ModuleCall& c) {
    const Args& a = c.args;
    glm::dvec3 n = arg_vec3(a, 0, "v", {1, 0, 0}, true);
    double n2 = glm::dot(n, n);
    if (!(n2 > 0)) arg_error(a, "normal v must not be zero");
    glm::dmat4 m(1.0);
    for (int col = 0; col < 3; ++col)
        for (int r = 0; r < 3; ++r) m[col][r] = (r == col ? 1.0 : 0.0) - 2 * n[r] * n[col] / n2;
    transformed(c, m);
}

// multmatrix as OpenSCAD 2021 reads it (measured from its STL): each entry
// that is a number replaces the identity's, the matrix is divided by its
// corner m[3][3], and the rest of the last row is dropped (no perspective).
// A matrix that is then not finite removes the children, with OpenSCAD's
// warning.
void openscad_multmatrix(ModuleCall& c) {
    const Args& a = c.args;
    if (!a[0].is_list()) arg_error(a, "m must be a 4x4 or 3x4 matrix of numbers");
    glm::dmat4 m(1.0);
    bool whole = a[0].as_list().size() == 3 || a[0].as_list().size() == 4;
    for (std::size_t r = 0; r < a[0].as_list().size() && r < 4; ++r) {
        const Value& row = a[0].as_list()[r];
        whole = whole && row.is_vector(4);
        for (std::size_t k = 0; row.is_list() && k < row.as_list().size() && k < 4; ++k)
            if (row.as_list()[k].is_number()) m[k][r] = row.as_list()[k].as_number();
    }
    if (!whole) c.warn("m is not a 4x4 or 3x4 matrix of numbers: the entries missing take the identity's, as OpenSCAD does");
    const glm::dvec3 perspective(m[0][3], m[1][3], m[2][3]);
    if (m[3][3] != 1) m /= m[3][3];
    bool finite = true;
    for (int k = 0; k < 4; ++k)
        for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(m[k][r]);
    if (finite && perspective != glm::dvec3(0))
        c.warn("the last row's " + to_repr(Value::list(ValueList{Value(perspective.x), Value(perspective.y), Value(perspective.z)})) +
               " is ignored, as OpenSCAD does (the matrix is used as an affine map)");
    m[0][3] = m[1][3] = m[2][3] = 0, m[3][3] = 1;
    if (finite) return transformed(c, m);
    GraphBuilder& g = c.graph();
    const std::size_t mark = g.mark();
    GhostFrameScope hide(c.state(), "multmatrix");
    c.children();
    c.warn("Transformation matrix contains Not-a-Number and/or Infinity - removing object.");
    g.pending.resize(mark);
}

void multmatrix(ModuleCall& c) {
    const Args& a = c.args;
    if (!a.has(0)) arg_error(a, "m is required");
    if (c.lenient()) return openscad_multmatrix(c);
    glm::dmat4 m = arg_matrix(a, 0, "m");
    transformed(c, m);
}

const ModuleEntry kTransforms[] = {
    {"union", ModuleKind::Operation, {}, boolean<NK::Union>},
    {"intersection", ModuleKind::Operation, {}, boolean<NK::Intersection>},
    {"difference", ModuleKind::Operation, {}, boolean<NK::Difference>},
    {"render", ModuleKind::Operation, {"convexity"}, plain_union},
    {"group", ModuleKind::Operation, {"convexity"}, plain_union},
    {"translate", ModuleKind::Operation, {"v"}, translate},
    {"rotate", ModuleKind::Operation, {"a", "v"}, rotate},
    {"scale", ModuleKind::Operation, {"v"}, scale},
    {"mirror", ModuleKind::Operation, {"v"}, mirror},
    {"multmatrix", ModuleKind::Operation, {"m"}, multmatrix},
};

}  // namespace

std::span<const ModuleEntry> transform_modules() { return kTransforms; }

}  // namespace kerf::eval

// Booleans and transforms (docs/spec.md §4). Matrices are world_from_child and
// compose like OpenSCAD's: the statement's matrix applies to its block.
#include <cmath>

#include "interpreter/degrees.hpp"
#include "interpreter/evaluator.hpp"
#include "interpreter/modules/args.hpp"

namespace kerf::eval {

namespace {

glm::dmat4 rot_x(double d) {
    double c = cos_deg(d), s = sin_deg(d);
    glm::dmat4 m(1.0);
    m[1][1] = c; m[1][2] = s;
    m[2][1] = -s; m[2][2] = c;
    return m;
}
glm::dmat4 rot_y(double d) {
    double c = cos_deg(d), s = sin_deg(d);
    glm::dmat4 m(1.0);
    m[0][0] = c; m[0][2] = -s;
    m[2][0] = s; m[2][2] = c;
    return m;
}
glm::dmat4 rot_z(double d) {
    double c = cos_deg(d), s = sin_deg(d);
    glm::dmat4 m(1.0);
    m[0][0] = c; m[0][1] = s;
    m[1][0] = -s; m[1][1] = c;
    return m;
}

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
        return rot_z(e[2]) * rot_y(e[1]) * rot_x(e[0]);
    }
    double deg = arg_number(a, 0, "a", 0);
    if (!a.has(1)) return rot_z(deg);
    glm::dvec3 v = arg_vec3(a, 1, "v", {0, 0, 1});
    double len = glm::length(v);
    if (!(len > 0)) arg_error(a, "axis v must not be zero");
    return rot_axis(deg, v / len);
}

}  // namespace

void Evaluator::transform(std::string_view name, const ast::Stmt& st, Scope& s) {
    using NK = graph::NodeKind;
    std::size_t mark = out_.mark();
    if (name == "union" || name == "intersection" || name == "difference") {
        const char* callee = name == "union" ? "union" : name == "intersection" ? "intersection" : "difference";
        match_args(callee, {}, st, s);
        eval_block(st.body, s, false);
        out_.make_node(mark, name == "union" ? NK::Union : name == "intersection" ? NK::Intersection : NK::Difference,
                       st.loc);
        return;
    }
    if (name == "render" || name == "group") {  // OpenSCAD's: a plain union here
        match_args(name == "render" ? "render" : "group", {"convexity"}, st, s);
        eval_block(st.body, s, false);
        out_.group(mark, st.loc);
        return;
    }
    glm::dmat4 m(1.0);
    if (name == "translate") {
        Args a = match_args("translate", {"v"}, st, s);
        glm::dvec3 v = arg_vec3(a, 0, "v", {0, 0, 0}, true);
        m[3] = glm::dvec4(v, 1.0);
    } else if (name == "rotate") {
        m = rotate_matrix(match_args("rotate", {"a", "v"}, st, s));
    } else if (name == "scale") {
        Args a = match_args("scale", {"v"}, st, s);
        glm::dvec3 f(1);
        if (a.has(0) && a[0].is_number()) f = glm::dvec3(arg_number(a, 0, "v", 1));
        else f = arg_vec3(a, 0, "v", f, true, 1);
        for (int k = 0; k < 3; ++k)
            if (f[k] == 0) arg_error(a, "factor must not be 0");
        m[0][0] = f.x;
        m[1][1] = f.y;
        m[2][2] = f.z;
    } else if (name == "mirror") {
        Args a = match_args("mirror", {"v"}, st, s);
        glm::dvec3 n = arg_vec3(a, 0, "v", {1, 0, 0}, true);
        double n2 = glm::dot(n, n);
        if (!(n2 > 0)) arg_error(a, "normal v must not be zero");
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m[c][r] = (r == c ? 1.0 : 0.0) - 2 * n[r] * n[c] / n2;
    } else {  // multmatrix
        Args a = match_args("multmatrix", {"m"}, st, s);
        if (!a.has(0)) arg_error(a, "m is required");
        const Value& v = a[0];
        bool ok = v.is_list() && (v.as_list().size() == 3 || v.as_list().size() == 4);
        if (ok)
            for (const Value& row : v.as_list()) ok = ok && row.is_vector(4);
        if (!ok) arg_error(a, "m must be a 4x4 or 3x4 matrix of numbers");
        const ValueList& rows = v.as_list();
        for (int r = 0; r < static_cast<int>(rows.size()); ++r)
            for (int c = 0; c < 4; ++c) {
                double x = rows[r].as_list()[c].as_number();
                if (!std::isfinite(x)) arg_error(a, "m must be finite");
                m[c][r] = x;
            }
        if (rows.size() == 4 && (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1))
            arg_error(a, "the last row must be [0, 0, 0, 1] (only affine transforms are supported)");
    }
    eval_block(st.body, s, false);
    if (out_.mark() == mark) return;
    out_.add_matrix(m);
    out_.wrap(mark, NK::Transform, static_cast<std::uint32_t>(out_.graph.matrices.size() - 1), st.loc);
}

}  // namespace kerf::eval

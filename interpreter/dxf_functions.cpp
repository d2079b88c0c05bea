// dxf_dim(file, layer, origin, scale, name) and dxf_cross(file, layer,
// origin, scale), OpenSCAD 2021.01's functions that read measurements from
// a drawing (docs/language.md, "2D drawings"). Not in the builtin table:
// they take their arguments by name, as OpenSCAD does (it ignores
// positional ones), and need the calling file's folder to find the drawing.
#include <string>

#include "interpreter/evaluator.hpp"
#include "interpreter/import/dxf.hpp"
#include "interpreter/import/dxf_dims.hpp"
#include "interpreter/import/mesh_import.hpp"

namespace kerf::eval {

Value Evaluator::call_dxf_function(const ast::Expr& e, Scope& s) {
    count_step(e.loc);
    const std::string fn = e.text;
    const bool dim = fn == "dxf_dim";
    std::string file, layer, name;
    glm::dvec2 origin(0);
    double scale = 1;
    // OpenSCAD's answer to a call it cannot serve: undef and a warning; kerf's
    // own dialect makes it an error.
    auto soft = [&](const SourceLoc& loc, const std::string& message) {
        if (!lenient_) throw SourceError(loc, fn + ": " + message);
        warn(loc, fn + ": " + message);
    };
    for (const ast::Binding& a : e.args) {
        const Value v = a.value ? eval(*a.value, s) : Value();
        auto text = [&](std::string& out) {
            if (v.is_string()) out = v.as_string();
            else if (!v.is_undef()) soft(a.loc, a.name + " must be a string, got " + to_repr(v));
        };
        if (a.name == "file") text(file);
        else if (a.name == "layer") text(layer);
        else if (a.name == "name" && dim) text(name);
        else if (a.name == "origin") {
            if (v.is_vector(2)) origin = {v.as_list()[0].as_number(), v.as_list()[1].as_number()};
            else if (!v.is_undef()) soft(a.loc, "origin must be [x, y], got " + to_repr(v));
        } else if (a.name == "scale") {
            if (v.is_number() && std::isfinite(v.as_number())) scale = v.as_number();
            else if (!v.is_undef()) soft(a.loc, "scale must be a number, got " + to_repr(v));
        } else if (a.name.empty()) {
            soft(a.loc, "takes its arguments by name (file = ..., layer = ...), as OpenSCAD does: ignored");
        } else {
            soft(a.loc, "unknown argument '" + a.name + "': ignored");
        }
    }
    if (file.empty()) return soft(e.loc, "no file given"), Value();
    std::string path;
    try {
        path = files_.resolve_data(file, e.loc);
    } catch (const SoftError& err) {
        return soft(e.loc, err.diagnostic().message), Value();
    }
    const std::string where = "'" + file + "', layer '" + layer + "'";
    try {
        if (dim) {
            for (const DxfDimension& d : read_dxf_dimensions(path, origin, scale)) {
                if ((!layer.empty() && d.layer != layer) || d.name != name) continue;
                if (auto v = dimension_value(d)) return Value(*v);
                return soft(e.loc, "dimension '" + name + "' in " + where + " has a type OpenSCAD does not read"), Value();
            }
            return soft(e.loc, "can't find dimension '" + name + "' in " + where), Value();
        }
        DxfOptions o;
        o.layer = layer, o.origin = origin, o.scale = scale;
        o.max_entities = opt_.limits.list_elements;
        const DxfShape shape = import_dxf(path, o);
        if (shape.lone_lines.size() >= 2) {
            const auto& a = shape.lone_lines[0];
            const auto& b = shape.lone_lines[1];
            if (auto p = line_cross(a[0], a[1], b[0], b[1])) return Value::list({Value(p->x), Value(p->y)});
        }
        return soft(e.loc, "can't find cross in " + where), Value();
    } catch (const MeshFormatError& err) {
        throw SourceError(e.loc, fn + "(\"" + file + "\"): " + err.what());
    }
}

}  // namespace kerf::eval

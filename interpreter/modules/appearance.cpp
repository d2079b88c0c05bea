// color(), material() (docs/spec.md §5) and the scene statements camera, light,
// background (docs/spec.md §6, top level only).
#include <cmath>

#include "interpreter/evaluator.hpp"
#include "interpreter/modules/args.hpp"

namespace kerf::eval {

namespace {
double unit_interval(const Args& a, std::size_t i, const char* name, double fallback) {
    double x = arg_number(a, i, name, fallback);
    if (x < 0 || x > 1) arg_error(a, std::string(name) + " must be in [0, 1], got " + format_number(x));
    return x;
}
}  // namespace

// An inner color() or material() starts from the enclosing material, so
// `material(specular = 1) color("red") sphere();` keeps the specular.
void Evaluator::appearance(std::string_view name, const ast::Stmt& st, Scope& s) {
    CurrentMaterial cur = materials_.empty() ? CurrentMaterial{} : materials_.back();
    if (name == "color") {
        Args a = match_args("color", {"c", "alpha"}, st, s);
        if (!a.has(0)) arg_error(a, "c is required");
        glm::dvec4 c = arg_color(a, 0, "c");
        if (a.has(1)) c.a = unit_interval(a, 1, "alpha", 1);
        cur.m.color = glm::dvec3(c);
        cur.m.alpha = c.a;
        if (!cur.interior_set) cur.m.interior = cur.m.color;
    } else {
        Args a = match_args("material", {"color", "interior", "diffuse", "specular", "shininess", "reflect"}, st, s);
        if (a.has(0)) {
            glm::dvec4 c = arg_color(a, 0, "color");
            cur.m.color = glm::dvec3(c);
            cur.m.alpha = c.a;
            if (!cur.interior_set) cur.m.interior = cur.m.color;
        }
        if (a.has(1)) {
            cur.m.interior = glm::dvec3(arg_color(a, 1, "interior"));
            cur.interior_set = true;
        }
        cur.m.diffuse = unit_interval(a, 2, "diffuse", cur.m.diffuse);
        cur.m.specular = unit_interval(a, 3, "specular", cur.m.specular);
        cur.m.shininess = arg_number(a, 4, "shininess", cur.m.shininess);
        if (cur.m.shininess < 0) arg_error(a, "shininess must not be negative, got " + format_number(cur.m.shininess));
        cur.m.reflect = unit_interval(a, 5, "reflect", cur.m.reflect);
    }
    std::size_t mark = out_.mark();
    materials_.push_back(cur);
    try {
        eval_block(st.body, s, false);
    } catch (...) {
        materials_.pop_back();
        throw;
    }
    materials_.pop_back();
    if (out_.mark() == mark) return;
    out_.graph.materials.push_back(cur.m);
    out_.wrap(mark, graph::NodeKind::Appearance, static_cast<std::uint32_t>(out_.graph.materials.size() - 1), st.loc);
}

void Evaluator::scene_statement(std::string_view name, const ast::Stmt& st, Scope& s, bool top_level) {
    if (!top_level) throw SourceError(st.loc, std::string(name) + " is only allowed at the top level");
    auto& g = out_.graph;
    if (name == "camera") {
        Args a = match_args("camera", {"position", "look_at", "up", "fov", "projection", "height"}, st, s);
        if (!st.body.empty()) arg_error(a, "takes no children");
        if (camera_loc_) throw SourceError(st.loc, "camera is already defined at line " + std::to_string(camera_loc_->line));
        if (!a.has(0)) arg_error(a, "position is required");
        csg::Camera c;
        c.position = arg_vec3(a, 0, "position", {0, 0, 0});
        c.look_at = arg_vec3(a, 1, "look_at", {0, 0, 0});
        c.up = arg_vec3(a, 2, "up", {0, 0, 1});
        c.fov = arg_number(a, 3, "fov", 40);
        glm::dvec3 dir = c.look_at - c.position;
        if (!(glm::length(dir) > 0)) arg_error(a, "position and look_at must differ");
        if (!(glm::length(glm::cross(dir, c.up)) > 1e-12 * glm::length(dir) * glm::length(c.up)))
            arg_error(a, "up must not be parallel to the view direction");
        if (a.has(4)) {
            if (!a[4].is_string() || (a[4].as_string() != "perspective" && a[4].as_string() != "orthographic"))
                arg_error(a, "projection must be \"perspective\" or \"orthographic\"");
            c.orthographic = a[4].as_string() == "orthographic";
        }
        if (c.orthographic) {
            c.height = arg_positive(a, 5, "height", 1);
        } else {
            if (a.has(5)) arg_error(a, "height is only for projection = \"orthographic\"");
            if (!(c.fov > 0 && c.fov < 180)) arg_error(a, "fov must be between 0 and 180, got " + format_number(c.fov));
        }
        g.camera = c;
        camera_loc_ = &st.loc;
    } else if (name == "light") {
        Args a = match_args("light", {"position", "direction", "color", "intensity"}, st, s);
        if (!st.body.empty()) arg_error(a, "takes no children");
        if (a.has(0) == a.has(1)) arg_error(a, "give position or direction (exactly one)");
        csg::Light l;
        if (a.has(0)) {
            l.position = arg_vec3(a, 0, "position", {0, 0, 0});
        } else {
            l.directional = true;
            glm::dvec3 d = arg_vec3(a, 1, "direction", {0, 0, -1});
            if (!(glm::length(d) > 0)) arg_error(a, "direction must not be zero");
            l.direction = d / glm::length(d);
        }
        if (a.has(2)) l.color = glm::dvec3(arg_color(a, 2, "color"));
        l.intensity = arg_number(a, 3, "intensity", 1);
        if (l.intensity < 0) arg_error(a, "intensity must not be negative, got " + format_number(l.intensity));
        g.lights.push_back(l);
    } else {
        Args a = match_args("background", {"color"}, st, s);
        if (!st.body.empty()) arg_error(a, "takes no children");
        if (background_loc_)
            throw SourceError(st.loc, "background is already defined at line " + std::to_string(background_loc_->line));
        if (!a.has(0)) arg_error(a, "color is required");
        g.background = glm::dvec3(arg_color(a, 0, "color"));
        background_loc_ = &st.loc;
    }
}

}  // namespace kerf::eval

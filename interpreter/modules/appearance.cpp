// color() and material() (docs/spec.md §5).
#include <cmath>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

namespace {
double unit_interval(const Args& a, std::size_t i, const char* name, double fallback) {
    double x = arg_number(a, i, name, fallback);
    if (x < 0 || x > 1) arg_error(a, std::string(name) + " must be in [0, 1], got " + format_number(x));
    return x;
}
using CurrentMaterial = ModuleState::CurrentMaterial;

// An inner color() or material() starts from the enclosing material, so
// `material(specular = 1) color("red") sphere();` keeps the specular.
// Materials are opaque until transparency is rendered: say so where an
// alpha below 1 is given rather than draw it opaque without a word.
void check_alpha(ModuleCall& c, double alpha) {
    if (alpha < 1) c.warn("alpha " + format_number(alpha) + " is ignored: kerf renders every solid opaque");
}

CurrentMaterial enclosing(ModuleCall& c) {
    auto& stack = c.state().materials;
    return stack.empty() ? CurrentMaterial{} : stack.back();
}

// The children with `cur` as the innermost appearance.
void appear(ModuleCall& c, const CurrentMaterial& cur) {

    GraphBuilder& g = c.graph();
    std::size_t mark = g.mark();
    auto& stack = c.state().materials;
    stack.push_back(cur);
    struct Pop {
        std::vector<CurrentMaterial>& s;
        ~Pop() { s.pop_back(); }
    } pop{stack};
    c.children();
    if (g.mark() == mark) return;
    g.graph.materials.push_back(cur.m);
    g.wrap(mark, graph::NodeKind::Appearance, static_cast<std::uint32_t>(g.graph.materials.size() - 1), c.st.loc);
}

void color(ModuleCall& c) {
    const Args& a = c.args;
    CurrentMaterial cur = enclosing(c);
    if (!a.has(0)) arg_error(a, "c is required");
    glm::dvec4 col = arg_color(a, 0, "c");
    if (a.has(1)) col.a = unit_interval(a, 1, "alpha", 1);
    check_alpha(c, col.a);
    cur.m.color = glm::dvec3(col);
    cur.m.alpha = col.a;
    if (!cur.interior_set) cur.m.interior = cur.m.color;
    appear(c, cur);
}

void material(ModuleCall& c) {
    const Args& a = c.args;
    CurrentMaterial cur = enclosing(c);
    if (a.has(0)) {
        glm::dvec4 col = arg_color(a, 0, "color");
        check_alpha(c, col.a);
        cur.m.color = glm::dvec3(col);
        cur.m.alpha = col.a;
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
    appear(c, cur);
}

const ModuleEntry kAppearance[] = {
    {"color", ModuleKind::Operation, {"c", "alpha"}, color},
    {"material", ModuleKind::Operation, {"color", "interior", "diffuse", "specular", "shininess", "reflect"}, material},
};

}  // namespace

std::span<const ModuleEntry> appearance_modules() { return kAppearance; }

}  // namespace kerf::eval

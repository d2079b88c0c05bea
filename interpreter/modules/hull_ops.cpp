// hull(), minkowski() and resize() in 3D (docs/spec.md §11): the call makes
// one graph node over its children, which lowering replaces by ordinary
// nodes once it knows the children's exact points and boxes (lower/
// geometry_ops.hpp, docs/lowering.md "Hull, Minkowski, resize"). Here:
// the arguments, OpenSCAD's rules for them, and the warnings for what the
// result only approximates.
#include <cmath>
#include <string>
#include <vector>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

namespace {

using NK = graph::NodeKind;
using P = csg::PrimKind;

// The children pending since `mark`, grouped into one node of `kind`
// (nothing at all when there are none). 2D children work on the unit slabs
// they are carried on (scene_graph.hpp): the hull of slabs is the slab of
// the hull, and lowering scales a sum of slabs back to one.
bool make(ModuleCall& c, std::size_t mark, NK kind) {
    GraphBuilder& g = c.graph();
    if (g.mark() == mark) {
        c.warn("no children: nothing is made");
        return false;
    }
    g.make_node(mark, kind, c.st.loc);
    return true;
}

// Warns once per kind of approximation found in the subtree at `id`:
// hull() and minkowski() use a difference's minuend and an intersection's
// first operand (a bigger solid than the exact result), and minkowski()
// takes a non-convex primitive as its convex hull.
void warn_approximations(ModuleCall& c, std::uint32_t id, bool minkowski) {
    const graph::SceneGraph& g = c.graph().graph;
    bool boolean = false, concave = false;
    std::vector<std::uint32_t> todo{id};
    while (!todo.empty()) {
        const graph::Node& n = g.nodes[todo.back()];
        todo.pop_back();
        if (n.kind == NK::Difference || n.kind == NK::Intersection) boolean = true;
        if (n.kind == NK::Primitive && (n.prim == P::Torus || n.prim == P::Lathe || n.prim == P::Mesh || n.prim == P::Prism))
            concave = true;
        for (std::uint32_t k = 0; k < n.child_count; ++k) todo.push_back(g.child_refs[n.first_child + k]);
    }
    if (boolean)
        c.warn("a difference() or intersection() inside is used as its first operand: the result may be larger "
               "than OpenSCAD's");
    if (minkowski && concave)
        c.warn("a torus, rotate_extrude, polyhedron or extruded polygon child is used as its convex hull: exact only "
               "when it is convex");
}

// hull() and minkowski(): the node, the curve tolerance for what lowering
// tessellates, the warnings (none for minkowski's single child: it is
// used unchanged).
template <NK kind>
void convex_op(ModuleCall& c) {
    const std::size_t mark = c.graph().mark();
    c.children();
    if (!make(c, mark, kind)) return;
    graph::Node& n = c.graph().graph.nodes[c.graph().pending.back()];
    n.p[0] = c.curve_tolerance();
    if (kind == NK::Hull || n.child_count > 1) warn_approximations(c, c.graph().pending.back(), kind == NK::Minkowski);
}

// resize(newsize, auto): newsize a list of up to 3 numbers (0 keeps an
// axis, unless `auto`), auto a bool or a list of up to 3 bools, as
// OpenSCAD 2021 reads them; anything else is an error (in .scad: a warning,
// the children unchanged, where OpenSCAD silently does nothing).
void resize(ModuleCall& c) {
    const Args& a = c.args;
    double size[3] = {0, 0, 0}, autos[3] = {0, 0, 0};
    if (!a.has(0) || !a[0].is_vector() || a[0].as_list().size() > 3)
        arg_error(a, "newsize must be a list of up to 3 numbers");
    const ValueList& ns = a[0].as_list();
    for (std::size_t i = 0; i < ns.size(); ++i) {
        size[i] = ns[i].as_number();
        if (!(size[i] >= 0) || !std::isfinite(size[i]))
            arg_error(a, "newsize must not be negative or infinite, got " + format_number(size[i]));
    }
    if (a.has(1) && a[1].is_bool()) {
        for (double& x : autos) x = a[1].as_bool();
    } else if (a.has(1)) {
        bool ok = a[1].is_list() && a[1].as_list().size() <= 3;
        if (ok)
            for (std::size_t i = 0; i < a[1].as_list().size(); ++i) {
                const Value& v = a[1].as_list()[i];
                ok = ok && v.is_bool();
                if (ok) autos[i] = v.as_bool();
            }
        if (!ok) arg_error(a, "auto must be true, false or a list of up to 3 of them");
    }
    const std::size_t mark = c.graph().mark();
    c.children();
    if (!make(c, mark, NK::Resize)) return;
    graph::Node& n = c.graph().graph.nodes[c.graph().pending.back()];
    for (int i = 0; i < 3; ++i) n.p[i] = size[i], n.p[3 + i] = autos[i];
}

const ModuleEntry kHullOps[] = {
    {"hull", ModuleKind::Operation, {}, convex_op<NK::Hull>},
    {"minkowski", ModuleKind::Operation, {"convexity"}, convex_op<NK::Minkowski>},
    {"resize", ModuleKind::Operation, {"newsize", "auto", "convexity"}, resize},
};

}  // namespace

std::span<const ModuleEntry> hull_modules() { return kHullOps; }

}  // namespace kerf::eval

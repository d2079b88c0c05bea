// Built-in modules (docs/spec.md §4–§6) as one table: each entry is a name,
// its kind, its parameters and a handler, so adding a solid is one entry.
// The evaluator matches a call's arguments to the parameters (modules/
// table.cpp), checks what the kind implies (solids and scene statements
// take no children; scene statements are top level only), then runs the
// handler with a ModuleCall: the matched arguments and the few evaluator
// services a module needs.
#pragma once
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <span>
#include <string_view>
#include <vector>

#include "interpreter/evaluator.hpp"

namespace kerf::eval {

class ModuleCall {
public:
    // `args` outlives the call (the caller's, not copied: it holds 18 values inline).
    ModuleCall(Evaluator& ev, const ast::Stmt& st, Scope& scope, const Args& args)
        : st(st), scope(scope), args(args), ev_(ev) {}
    // A temporary Args would dangle once the constructor returns.
    ModuleCall(Evaluator&, const ast::Stmt&, Scope&, Args&&) = delete;

    const ast::Stmt& st;
    Scope& scope;
    const Args& args;

    // Evaluates the statement's block of children (their nodes go on the
    // builder's pending stack).
    void children();
    GraphBuilder& graph();
    ModuleState& state();
    Loader& files();
    const EvalLimits& limits() const;
    double curve_tolerance() const;  // EvalOptions::curve_tolerance
    FacetVars facet_vars() const;    // the $fn, $fa, $fs in force for this call
    FacetMode facet_mode() const;    // EvalOptions::facets
    bool path_integrator() const;    // EvalOptions::path_integrator
    // EvalOptions::resolve_geometry_ops (may be empty).
    const std::function<bool(const graph::SceneGraph&, graph::SceneGraph&)>& geometry_ops() const;
    // A primitive node at the statement, counted against the limit.
    void add_primitive(csg::PrimKind kind, std::initializer_list<double> p, std::uint32_t index = 0);
    // A warning at the statement (Evaluator::warn).
    void warn(std::string message);
    bool lenient() const { return ev_.lenient(); }  // the OpenSCAD dialect
    // This call's curve is exact: counted for the one warning if facets were asked for.
    void exact_curve() { ev_.exact_curve(args, st.loc); }
    // An operation on 2D shapes: its children pending[mark..] taken off the
    // stack, the 2D ones returned. A 3D child is an error in .sdl and
    // ignored with a warning in .scad, as OpenSCAD does; `verb` says what
    // the operation does ("revolves") in both messages.
    std::vector<std::uint32_t> flat_children(std::size_t mark, const char* verb);
    // The graph's index of a new mesh (for a Mesh primitive).
    std::uint32_t add_mesh(graph::PolygonMesh mesh);

private:
    Evaluator& ev_;
};

enum class ModuleKind : std::uint8_t {
    Solid,      // no children
    Operation,  // booleans, transforms, appearance: apply to their children
    Setup,      // camera, light, background: top level only, no children
};

struct ModuleEntry {
    const char* name;
    ModuleKind kind;
    std::vector<const char*> params;  // positional order; named arguments by these names
    void (*handler)(ModuleCall&);
};

// The entries of each group (solids.cpp, shapes2d.cpp, transforms.cpp, appearance.cpp,
// setup.cpp); table.cpp merges them into one sorted table.
std::span<const ModuleEntry> solid_modules();
std::span<const ModuleEntry> transform_modules();
std::span<const ModuleEntry> appearance_modules();
std::span<const ModuleEntry> setup_modules();
std::span<const ModuleEntry> shape2d_modules();  // shapes2d.cpp
std::span<const ModuleEntry> revolve_modules();  // rotate_extrude.cpp
std::span<const ModuleEntry> text_modules();     // text.cpp
std::span<const ModuleEntry> hull_modules();     // hull_ops.cpp: hull, minkowski, resize
std::span<const ModuleEntry> offset_modules();   // offset.cpp
std::span<const ModuleEntry> projection_modules();  // projection.cpp
std::span<const ModuleEntry> surface_modules();     // surface.cpp

// The built-in module called `name`, or null.
const ModuleEntry* find_module(std::string_view name);
// The same as a place in the table (-1: none), and the entry at a place:
// what a statement's dispatch cache keeps (ast::Stmt::dispatch).
int find_module_index(std::string_view name);
const ModuleEntry& module_entry(int index);
// Every built-in module's name (for "did you mean").
std::vector<std::string_view> module_names();

}  // namespace kerf::eval

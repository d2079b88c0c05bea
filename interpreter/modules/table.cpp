// One sorted table over the module groups, the dispatch of a call to its
// entry, and the matching of arguments to parameters.
#include <algorithm>
#include <memory>
#include <new>
#include <stdexcept>

#include "interpreter/modules/args.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {

namespace {

// A call's argument values, as many as the module has parameters,
// constructed in place: an array of kMaxParams values would construct and
// destroy all 18 for every call.
class ArgValues {
public:
    explicit ArgValues(std::size_t n) : n_(n) { std::uninitialized_default_construct_n(data(), n); }
    ~ArgValues() { std::destroy_n(data(), n_); }
    ArgValues(const ArgValues&) = delete;
    ArgValues& operator=(const ArgValues&) = delete;
    Value* data() { return std::launder(reinterpret_cast<Value*>(raw_)); }

private:
    alignas(Value) unsigned char raw_[Args::kMaxParams * sizeof(Value)];
    std::size_t n_;
};

// Fills a (fresh, its values ArgValues of e) for a call of e.
void match_args(Evaluator& ev, const ModuleEntry& e, const ast::Stmt& st, Scope& s, Args& a) {
    const std::size_t n = e.params.size();
    a.callee = e.name;
    a.call = &st;
    std::size_t positional = 0;
    for (const ast::Binding& b : st.args) {
        std::size_t i = n;
        if (b.name.empty()) {
            if (positional >= n) {
                if (ev.lenient()) {  // OpenSCAD's warnings, the argument dropped
                    ev.warn(b.loc, "Too many unnamed arguments supplied");
                    continue;
                }
                throw SourceError(b.loc, std::string("too many arguments for '") + e.name + "' (takes " +
                                             std::to_string(n) + ")");
            }
            i = positional++;
        } else {
            if (b.name[0] == '$') {  // bound for the call (builtin_module); $fn, $fa, $fs cut its curves
                const bool facet = b.name == "$fn" || b.name == "$fa" || b.name == "$fs";
                a.facet_args = a.facet_args || facet;
                Value v = b.value ? ev.eval(*b.value, s) : Value();
                if (b.name == "$fn" && v.is_number()) a.fn = v.as_number();
                a.dollars.push_back(DynVar{b.name, std::move(v)});
                continue;
            }
            for (std::size_t j = 0; j < n; ++j)
                if (b.name == e.params[j]) i = j;
            if (i == n && ev.lenient()) {
                ev.warn(b.loc, "variable " + b.name + " not specified as parameter");
                continue;
            }
            if (i == n) throw SourceError(b.loc, "unknown argument '" + b.name + "' for '" + e.name + "'");
        }
        if (a.given[i] && ev.lenient()) ev.warn(b.loc, std::string("argument ") + e.params[i] + " supplied more than once");
        else if (a.given[i])
            throw SourceError(b.loc, std::string("argument '") + e.params[i] + "' given twice to '" + e.name + "'");
        a.given[i] = true;
        a.values[i] = b.value ? ev.eval(*b.value, s) : Value();
    }
}

}  // namespace

namespace {
const std::vector<const ModuleEntry*>& module_table() {
    static const std::vector<const ModuleEntry*> table = [] {
        std::vector<const ModuleEntry*> all;
        for (auto group : {solid_modules(), transform_modules(), appearance_modules(), setup_modules(), shape2d_modules(),
                           revolve_modules(), text_modules(), hull_modules(), offset_modules(), projection_modules(),
                           surface_modules()})
            for (const ModuleEntry& e : group) {
                if (e.params.size() > Args::kMaxParams) throw std::logic_error(std::string("built-in module ") + e.name + ": more parameters than Args holds");
                all.push_back(&e);
            }
        std::sort(all.begin(), all.end(),
                  [](const ModuleEntry* a, const ModuleEntry* b) { return std::string_view(a->name) < b->name; });
        return all;
    }();
    return table;
}
}  // namespace

std::vector<std::string_view> module_names() {
    std::vector<std::string_view> out;
    for (const ModuleEntry* e : module_table()) out.push_back(e->name);
    return out;
}

int find_module_index(std::string_view name) {
    const auto& table = module_table();
    auto it = std::lower_bound(table.begin(), table.end(), name,
                               [](const ModuleEntry* e, std::string_view n) { return e->name < n; });
    return it != table.end() && (*it)->name == name ? static_cast<int>(it - table.begin()) : -1;
}

const ModuleEntry& module_entry(int index) { return *module_table()[static_cast<std::size_t>(index)]; }

const ModuleEntry* find_module(std::string_view name) {
    const int i = find_module_index(name);
    return i < 0 ? nullptr : &module_entry(i);
}

void Evaluator::builtin_module(const ModuleEntry& entry, const ast::Stmt& st, Scope& s, bool top_level) {
    const ModuleEntry* e = &entry;
    if (e->kind == ModuleKind::Setup && !top_level)
        throw SourceError(st.loc, st.name + " is only allowed at the top level");
    ArgValues values(e->params.size());
    Args a;
    a.values = values.data();
    match_args(*this, *e, st, s, a);
    if (e->kind != ModuleKind::Operation && !st.body.empty()) {
        if (!lenient_) arg_error(a, e->kind == ModuleKind::Solid ? "a solid takes no children" : "takes no children");
        warn(st.loc, std::string("module ") + e->name + "() does not support child modules");  // ignored, as OpenSCAD
    }
    // The call's `$` arguments hold for it and its children, as in OpenSCAD.
    DynRestore restore(dyn_);
    for (DynVar& d : a.dollars) dyn_.push_back(std::move(d));
    ModuleCall call(*this, st, s, a);
    if (lenient_) return builtin_module_lenient(*e, call);
    e->handler(call);
}

// Out of line, so the strict path above stays as small as it was.
[[gnu::noinline]] void Evaluator::builtin_module_lenient(const ModuleEntry& entry, ModuleCall& call) {
    const ModuleEntry* e = &entry;
    const ast::Stmt& st = call.st;
    Scope& s = call.scope;
    // The OpenSCAD dialect: an argument OpenSCAD would not stop at (a zero
    // axis, a zero or negative size, undef) makes an operation the identity
    // on its children and a solid nothing, with the strict message as the
    // warning. Limits still stop.
    const std::size_t mark = out_.mark(), ghosts = modules_.ghosts.size();
    try {
        e->handler(call);
    } catch (const SoftError& err) {
        warn(err.diagnostic().loc, err.diagnostic().message + (e->kind == ModuleKind::Operation
                                                                   ? " (the children are used unchanged)"
                                                                   : " (nothing is made)"));
        out_.pending.resize(mark);
        modules_.ghosts.resize(ghosts);  // the children's ghosts, if they ran, are recorded again below
        if (e->kind == ModuleKind::Operation) {
            eval_block(st.body, s, false);
            out_.group(mark, st.loc);
        }
    }
}

void ModuleCall::children() { ev_.eval_block(st.body, scope, false); }
GraphBuilder& ModuleCall::graph() { return ev_.out_; }
ModuleState& ModuleCall::state() { return ev_.modules_; }
Loader& ModuleCall::files() { return ev_.files_; }
const EvalLimits& ModuleCall::limits() const { return ev_.opt_.limits; }
double ModuleCall::curve_tolerance() const { return ev_.opt_.curve_tolerance; }
FacetVars ModuleCall::facet_vars() const { return ev_.facet_vars(); }
FacetMode ModuleCall::facet_mode() const { return ev_.facet_mode(); }
bool ModuleCall::path_integrator() const { return ev_.opt_.path_integrator; }
const std::function<bool(const graph::SceneGraph&, graph::SceneGraph&)>& ModuleCall::geometry_ops() const {
    return ev_.opt_.resolve_geometry_ops;
}

void ModuleCall::add_primitive(csg::PrimKind kind, std::initializer_list<double> p, std::uint32_t index) {
    const std::uint64_t limit = ev_.opt_.limits.primitives;
    if (++state().primitives > limit)
        throw RunLimitError(st.loc, "primitive limit " + std::to_string(limit) + " exceeded");
    GraphBuilder& g = graph();
    graph::Node& n = g.emplace(st.loc);
    n.kind = graph::NodeKind::Primitive;
    n.prim = kind;
    n.index = index;
    std::size_t i = 0;
    for (double x : p) n.p[i++] = x;
    g.push(static_cast<std::uint32_t>(g.graph.nodes.size() - 1));
}

std::vector<std::uint32_t> ModuleCall::flat_children(std::size_t mark, const char* verb) {
    GraphBuilder& g = graph();
    std::vector<std::uint32_t> shapes;
    for (std::size_t i = mark; i < g.pending.size(); ++i) {
        const graph::Node& n = g.graph.nodes[g.pending[i]];
        if (n.flat)
            shapes.push_back(g.pending[i]);
        else if (lenient())
            warn(std::string("ignoring a 3D child (") + args.callee + " " + verb + " 2D shapes)");
        else
            throw SourceError(n.loc, std::string(args.callee) + ": " + verb + " 2D shapes, not 3D solids");
    }
    g.pending.resize(mark);
    return shapes;
}

void ModuleCall::warn(std::string message) { ev_.warn(st.loc, std::string(args.callee) + ": " + std::move(message)); }

std::uint32_t ModuleCall::add_mesh(graph::PolygonMesh mesh) {
    auto& meshes = graph().graph.meshes;
    meshes.push_back(std::move(mesh));
    return static_cast<std::uint32_t>(meshes.size() - 1);
}

}  // namespace kerf::eval

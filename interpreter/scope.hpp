// Lexical scopes of the evaluator (docs/spec.md §3). A Scope lives on the C++ stack
// of the block, call or loop that made it and points to its parent, so a
// binding costs no heap allocation beyond its slot; functions and modules
// are not first-class values, so no definition can outlive its scope, and
// `use`d files' scopes live as long as the evaluator.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "grammar/ast.hpp"
#include "interpreter/value.hpp"

namespace kerf::eval {

struct Scope;

// The module instantiation whose body is being evaluated: what children()
// and $children refer to.
struct ModuleFrame {
    const std::vector<ast::StmtPtr>* children = nullptr;  // call-site child statements
    Scope* caller = nullptr;                              // the scope they evaluate in
    std::size_t child_count = 0;                          // $children
};

struct VarSlot {
    std::string_view name;
    Value value;
    const SourceLoc* loc = nullptr;  // where it is bound (for "already defined")
    bool ready = false;              // false while the block's earlier assignments run
};

struct Scope {
    Scope* parent = nullptr;
    const ModuleFrame* module = nullptr;  // inherited from the parent
    std::vector<VarSlot> vars;
    std::vector<const ast::Stmt*> functions;
    std::vector<const ast::Stmt*> modules;
    std::vector<Scope*> used;  // top-level scopes of `use`d files

    Scope() = default;
    explicit Scope(Scope* p) : parent(p), module(p ? p->module : nullptr) {}
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

    VarSlot* find_local(std::string_view name) {
        for (VarSlot& v : vars)
            if (v.name == name) return &v;
        return nullptr;
    }
};

// `$` variables are dynamically scoped, as in OpenSCAD: one stack per
// evaluator, pushed by bindings and calls, cut back when a scope ends.
inline bool is_dollar(std::string_view name) { return !name.empty() && name[0] == '$'; }

struct DynVar {
    std::string_view name;
    Value value;
};

// Restores the dynamic stack when a scope that may have pushed to it ends.
struct DynRestore {
    std::vector<DynVar>& dyn;
    std::size_t size;
    explicit DynRestore(std::vector<DynVar>& d) : dyn(d), size(d.size()) {}
    ~DynRestore() { dyn.resize(size); }
};

// "line 4", or "lib.sdl:4" when `there` is in another file than `here`: how
// "already defined at ..." messages name the earlier binding.
inline std::string line_ref(const SourceLoc& here, const SourceLoc& there) {
    if (there.file && here.file && there.file->path != here.file->path)
        return there.file->path + ":" + std::to_string(there.line);
    return "line " + std::to_string(there.line);
}

}  // namespace kerf::eval

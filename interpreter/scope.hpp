// Lexical scopes of the evaluator (docs/spec.md §3). A Scope lives on the C++ stack
// of the block, call or loop that made it and points to its parent, so a
// binding costs no heap allocation beyond its slot; `use`d files' scopes
// live as long as the evaluator. A function value (Closure) cannot point
// into the stack: it copies the bindings its body may read from the scopes
// between it and its file, and keeps only the file's scope as parent.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
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
    std::size_t calls = 0;  // the caller's depth of Evaluator::calls_: children run there
};

struct VarSlot {
    std::string_view name;
    Value value;
    const SourceLoc* loc = nullptr;  // where it is bound (for "already defined")
    bool ready = false;              // false while the block's earlier assignments run
    bool failed = false;             // its top-level binding was an error (reported)
};

struct Scope {
    Scope* parent = nullptr;
    const ModuleFrame* module = nullptr;  // inherited from the parent
    std::vector<VarSlot> vars;            // grow with add(), shrink with truncate()
    std::vector<const ast::Stmt*> functions;
    std::vector<const ast::Stmt*> modules;
    std::vector<Scope*> used;  // top-level scopes of `use`d files
    bool file = false;         // a file's top level: lives as long as the run

    Scope() = default;
    explicit Scope(Scope* p) : parent(p), module(p ? p->module : nullptr) {}
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

    // The first slot bound to `name` in this scope. Small scopes (calls,
    // loops) are searched in order; a scope that grows past kIndexFrom
    // names (a file of thousands of top-level bindings) gets a hash index,
    // so binding and looking up n names stays linear in n, not quadratic.
    VarSlot* find_local(std::string_view name) {
        if (index_) [[unlikely]] return find_indexed(name);
        for (VarSlot& v : vars)
            if (same_name(v.name, name)) return &v;
        return nullptr;
    }
    // Names are short (`i`, `r`, `size`): compared byte by byte inline, a
    // memcmp call only past 8 bytes.
    static bool same_name(std::string_view a, std::string_view b) {
        if (a.size() != b.size()) return false;
        if (a.size() > 8) return a == b;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a[i] != b[i]) return false;
        return true;
    }
    void add(VarSlot v) {
        vars.push_back(std::move(v));
        if (index_) index_->emplace(vars.back().name, std::uint32_t(vars.size() - 1));
        else if (vars.size() > kIndexFrom) build_index();
    }
    void truncate(std::size_t n) {
        if (index_)
            for (std::size_t i = n; i < vars.size(); ++i) {
                auto it = index_->find(vars[i].name);
                if (it != index_->end() && it->second == i) index_->erase(it);
            }
        vars.resize(n);
    }

private:
    static constexpr std::size_t kIndexFrom = 32;
    // Out of line: the hash lookup's registers would crowd every name
    // search's loop (a lookup in a loop's scope).
    [[gnu::noinline]] VarSlot* find_indexed(std::string_view name) {
        auto it = index_->find(name);
        return it == index_->end() ? nullptr : &vars[it->second];
    }
    std::unique_ptr<std::unordered_map<std::string_view, std::uint32_t>> index_;
    void build_index() {
        index_ = std::make_unique<std::unordered_map<std::string_view, std::uint32_t>>();
        index_->reserve(2 * vars.size());
        for (std::size_t i = 0; i < vars.size(); ++i) index_->emplace(vars[i].name, std::uint32_t(i));
    }
};

// A function literal's value: the literal (parameters, body) and what it
// captured. env's parent is the scope of the file the literal is in, which
// lives as long as the run; env itself holds copies of the inner bindings
// and function definitions the body names.
struct Closure {
    const ast::Expr* literal;
    mutable Scope env;  // a call's scope points to it; calls never change it
    Closure(const ast::Expr* lit, Scope* file_scope) : literal(lit), env(file_scope) { env.module = nullptr; }
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
    ~DynRestore() {
        if (dyn.size() != size) dyn.resize(size);  // most scopes push nothing
    }
};

// "line 4", or "lib.sdl:4" when `there` is in another file than `here`: how
// "already defined at ..." messages name the earlier binding.
inline std::string line_ref(const SourceLoc& here, const SourceLoc& there) {
    if (there.file && here.file && there.file->path != here.file->path)
        return there.file->path + ":" + std::to_string(there.line);
    return "line " + std::to_string(there.line);
}

}  // namespace kerf::eval

// The tree-walking evaluator: expressions to Values, statements to scene
// graph nodes. One Evaluator per run; it owns the run's files (its Loader
// keeps every SourceLoc and AST pointer valid), the limit counters, the
// dynamic `$` variables and the graph being built.
//
// Strictness decisions (docs/spec.md §3 leaves them to the implementation):
// - A block's assignments run first, in source order, before its other
//   statements (as in OpenSCAD), so a statement may use a name assigned
//   below it. An assignment's expression may use only names assigned above
//   it in the same block: a later one is an error ("'y' is used before its
//   definition at line 4"), where OpenSCAD would yield undef.
// - Functions and modules are visible in their whole block (hoisted).
// - Missing arguments without a default are undef; operators and solids
//   reject undef where they need a value.
// - Indexing out of range, or with a non-integer, is an error.
// The OpenSCAD dialect (`lenient_`, docs/openscad.md) changes exactly these,
// each only on the path that would otherwise be an error, so strict runs
// pay one untaken branch: a name bound twice in a block takes the last
// value, evaluated at the first binding's place, with a warning; a name not
// yet bound in its block is looked up outside (`w = w / 2;` in a module
// reads the argument); an unknown variable, function or module, a
// SoftError of a built-in or an operator, and argument mismatches are
// undef (or nothing) and a warning; indexing follows OpenSCAD silently.
// `assert` and every limit still stop the run.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "grammar/ast.hpp"
#include "interpreter/builtins/builtins.hpp"
#include "interpreter/interpreter.hpp"
#include "interpreter/graph_builder.hpp"
#include "interpreter/loader.hpp"
#include "interpreter/modules/state.hpp"
#include "interpreter/operators.hpp"
#include "interpreter/scope.hpp"
#include "interpreter/value.hpp"

namespace kerf::eval {

// The lowest address evaluation may use on this thread's stack (set by the
// thread that runs it, with a safety margin): a raised call-depth limit or
// a pathological expression ends in a located error, never in a crash.
extern thread_local const char* stack_floor;

// An error that ends the run at once: a limit of the whole run (steps,
// loop iterations, primitives, memory) was reached, so every statement
// after it would fail the same way.
class RunLimitError : public SourceError {
public:
    using SourceError::SourceError;
};

// A name whose top-level binding failed (already reported) was read: the
// statement reading it is given up silently, not reported as a second error.
class CascadeError : public SourceError {
public:
    using SourceError::SourceError;
};

// A statement list after `include` expansion, with its definitions sorted
// out: computed once per list and cached.
struct BlockInfo {
    std::vector<const ast::Stmt*> assigns;    // in source order
    std::vector<const ast::Stmt*> functions;
    std::vector<const ast::Stmt*> modules;
    std::vector<Scope*> used;
    std::vector<const ast::Stmt*> children;   // statements that produce solids or run (not definitions)
    bool needs_scope = false;
};

// The facet settings a curve is cut by (docs/openscad.md, "Facets").
struct FacetVars {
    double fn = 0, fa = 12, fs = 2;
};

// Arguments of a built-in module matched to its parameter names
// (modules/module_call.hpp).
struct Args {
    // The most parameters of any built-in module (material's); the table
    // refuses more (modules/table.cpp). The values live in the caller's
    // frame (ArgValues, modules/table.cpp), so a call allocates nothing.
    static constexpr std::size_t kMaxParams = 18;
    const char* callee;
    const ast::Stmt* call;
    Value* values;  // one per parameter of the module
    std::array<bool, kMaxParams> given{};
    double fn = 0;  // a $fn given in the call itself (docs/openscad.md, "Facets")
    bool facet_args = false;  // a $fn, $fa or $fs given in the call
    // Every `$` argument of the call, bound for its children and its own
    // facet settings as OpenSCAD binds them (the call's dynamic scope).
    std::vector<DynVar> dollars;

    bool has(std::size_t i) const { return given[i]; }
    const Value& operator[](std::size_t i) const { return values[i]; }
};

class Evaluator {
public:
    explicit Evaluator(const EvalOptions& options);
    ~Evaluator();

    // Evaluates a whole parsed program (the main file).
    graph::SceneGraph run(ast::Program program);
    // What kerf accepted but cannot honour (docs/spec.md §11): once per
    // place and message, with a count when met again (a loop).
    void warn(const SourceLoc& loc, std::string message);
    std::vector<Diagnostic> take_warnings() { return std::move(warnings_); }
    // A curve made exact although $fn/$fa/$fs asked for facets (a call's
    // own, or set around it): counted, one warning at the end of the run.
    void exact_curve(const Args& a, const SourceLoc& loc);
    // The $fn, $fa and $fs in force (innermost binding, OpenSCAD's defaults
    // 0, 12, 2 otherwise), and what --facets does with them.
    FacetVars facet_vars() const;
    FacetMode facet_mode() const { return opt_.facets; }
    // Top-level statements fail independently: each error is kept and the
    // run goes on with the next statement, up to kMaxErrors; run() then
    // throws the first with all of them (SourceError::reported).
    static constexpr std::size_t kMaxErrors = 20;
    bool lenient() const { return lenient_; }  // the OpenSCAD dialect

    // Expressions (eval_expr.cpp). A number literal or a name, the leaves
    // of most expressions, inline: no call through the dispatch of every
    // kind for them (docs/performance.md, "The interpreter's per-call costs").
    [[gnu::always_inline]] Value eval(const ast::Expr& e, Scope& s) {
        if (e.kind == ast::ExprKind::Number) return Value(e.number);
        if (e.kind == ast::ExprKind::Ident) return lookup(e, s);
        return eval_node(e, s);
    }

private:
    // eval_expr.cpp
    Value eval_node(const ast::Expr& e, Scope& s);  // any kind
    Value eval_list(const ast::Expr& e, Scope& s);
    Value eval_range(const ast::Expr& e, Scope& s);
    Value eval_unary(const ast::Expr& e, Scope& s);
    Value eval_binary(const ast::Expr& e, Scope& s);
    Value binary_values(const ast::Expr& e, const Value& a, const Value& b);
    Value eval_index(const ast::Expr& e, Scope& s);
    Value eval_member(const ast::Expr& e, Scope& s);
    Value eval_let(const ast::Expr& e, Scope& s);
    Value lookup(const ast::Expr& e, Scope& s);
    Value lookup_slow(const ast::Expr& e, Scope& s);  // lookup's other answers, and its errors
    Value unknown_variable(const ast::Expr& e);  // the OpenSCAD dialect: undef and a warning
    Value call_function(const ast::Expr& e, Scope& s);
    // The user function `name` seen from s (and the scope it is defined in), or null.
    const ast::Stmt* find_function(std::string_view name, Scope& s, Scope*& def_scope);
    Value run_body(const ast::Stmt& def, Scope& def_scope, Scope& callee);
    static bool calls_itself_last(const ast::Expr& e, std::string_view name);
    void expand_element(const ast::Expr& e, Scope& s, ValueList& out);
    void expand_for(const ast::Expr& e, std::size_t k, Scope& s, ValueList& out);
    void expand_for_c(const ast::Expr& e, Scope& s, ValueList& out);
    void push_element(ValueList& out, Value v, const SourceLoc& loc);
    [[noreturn]] void list_limit(const SourceLoc& loc) const;  // the list size limit's error, at loc
    void do_echo(const std::vector<ast::Binding>& args, Scope& s, const SourceLoc& loc);
    Value call_builtin(const ast::Expr& e, Scope& s);
    Value call_dxf_function(const ast::Expr& e, Scope& s);  // dxf_functions.cpp: dxf_dim, dxf_cross
    // function_values.cpp: function literals, their captures and calls.
    Value make_closure(const ast::Expr& e, Scope& s);
    Value call_closure(const Value& f, const std::vector<ast::Binding>& args, Scope& caller, const SourceLoc& loc,
                       const std::string& name);
    Value apply(const ast::Expr& e, Scope& s);
    const Value* find_value(std::string_view name, Scope& s);  // quiet lookup: null if unbound
    // suggest.cpp: "; did you mean 'x'?" from the names visible in s of
    // one kind (or ""), for the strict "undefined" errors.
    enum class NameKind { Variable, Function, Module };
    std::string did_you_mean(std::string_view name, Scope& s, NameKind kind);
    void check_builtin_name(const Builtin& fn, const ast::Binding& a, std::size_t i, std::size_t count);
    // The OpenSCAD dialect's answer to an operator that threw a SoftError;
    // `tried` is the strict attempt's budget: its work is charged, but the
    // fallback gets a fresh list size limit (the values the failed attempt
    // made are gone).
    Value lenient_operator(const ast::Expr& e, const Value& a, const Value* b, const OpBudget& tried);
    void do_assert(const std::vector<ast::Binding>& args, Scope& s, const SourceLoc& loc);
    // Counts (and charges) the iterations of a `for` over v; a string becomes
    // the list of its characters (as in OpenSCAD), so v may be replaced.
    std::uint64_t iteration_count(Value& v, const SourceLoc& loc);

    // eval_stmt.cpp
    const BlockInfo& prepare(const std::vector<ast::StmtPtr>& stmts);
    void warn_overwritten(const ast::Stmt& earlier, const ast::Stmt& later);
    void flatten(const std::vector<ast::StmtPtr>& stmts, std::vector<const ast::Stmt*>& out);
    std::string find_library(const ast::Stmt& st);
    void bind_block(const BlockInfo& info, Scope& scope, bool top_level);
    void eval_block(const std::vector<ast::StmtPtr>& stmts, Scope& s, bool top_level = false);
    void eval_stmt(const ast::Stmt& st, Scope& s, bool top_level);
    void eval_plain(const ast::Stmt& st, Scope& s, bool top_level);
    void instantiate(const ast::Stmt& st, Scope& s, bool top_level);
    void call_module(const ast::Stmt& def, Scope& def_scope, const ast::Stmt& call, Scope& s);
    void stmt_for(const ast::Stmt& st, std::size_t k, Scope& loop, Scope& s);
    void stmt_children(const ast::Stmt& st, Scope& s);
    // ghosts.cpp: a `%` or `#` statement's subtree `node` as a ghost, under
    // the transforms around it; at the end of the run, the ghost trees.
    void record_ghost(const ast::Stmt& st, csg::GhostKind kind, std::uint32_t node);
    void build_ghost_roots(const SourceLoc& top);
    Scope* load_use(const ast::Stmt& st);

    // Binding helpers (eval_stmt.cpp): `$` names go to the dynamic stack.
    void bind_params(const std::vector<ast::Binding>& params, const std::vector<ast::Binding>& args,
                     const std::string& callee, Scope& caller, Scope& callee_scope, const SourceLoc& loc);
    void bind(Scope& s, std::string_view name, Value v, const SourceLoc* loc);
    void bind_sequential(const std::vector<ast::Binding>& bindings, Scope& s, const char* what);

    // modules/table.cpp: a call of the built-in module e.
    void builtin_module(const struct ModuleEntry& e, const ast::Stmt& st, Scope& s, bool top_level);
    void builtin_module_lenient(const ModuleEntry& e, class ModuleCall& call);

    // Call-site notes (interpreter.cpp): the user-level calls being
    // evaluated, innermost last. bind_params pushes a call once its
    // arguments are evaluated (an error in them is the caller's); traced()
    // pops it and gives an error leaving it the notes of the stack it left.
    struct CallSite {
        std::string_view name;
        const SourceLoc* at;
    };
    std::vector<CallSite> calls_;
    static constexpr std::size_t kMaxCallNotes = 10;
    std::vector<Diagnostic> call_notes() const;
    template <class F>
    auto traced(F&& body) -> decltype(body()) {
        const std::size_t outer = calls_.size();
        struct Pop {
            std::vector<CallSite>& calls;
            std::size_t size;
            ~Pop() { calls.resize(size); }
        } pop{calls_, outer};
        try {
            return body();
        } catch (SourceError& e) {
            if (calls_.size() > outer && !e.has_call_notes()) e.set_call_notes(call_notes());
            throw;
        }
    }

    // Limits.
    void count_step(const SourceLoc& loc);
    void count_made(const Value& v, const SourceLoc& loc);  // a built-in's result (eval_expr.cpp)
    void count_work(std::uint64_t elements, const SourceLoc& loc);  // elements made or compared
    std::uint64_t work_cap() const;  // the elements count_work takes before the step limit
    void count_iterations(std::uint64_t n, const SourceLoc& loc);
    struct DepthGuard;

    const EvalOptions& opt_;
    const bool lenient_;     // the OpenSCAD dialect
    const std::uint64_t call_depth_;  // call_depth_limit(): the deepest call nesting allowed
    std::string main_path_;  // the main file (OpenSCAD's overwrite warnings name others)
    GraphBuilder out_;
    Scope root_;  // PI and other constants; parent of every file's scope
    std::vector<DynVar> dyn_;
    std::vector<std::string_view> module_stack_;  // user module calls, outermost first (parent_module)
    std::uint64_t depth_ = 0, steps_ = 0, iterations_ = 0, echo_bytes_ = 0;

    std::unordered_map<const void*, BlockInfo> blocks_;
    // prepare()'s last answer: a loop evaluates the same block (a
    // translate()'s child) on every pass. Entries of blocks_ are never
    // erased and stay where they are, so the pointer stays valid.
    const void* last_block_ = nullptr;
    const BlockInfo* last_info_ = nullptr;
    // Whether any block prepared so far defines a module: only those put
    // modules in scopes (bind_block), so until one does, a call's search
    // of the scopes for a user module would find none (instantiate).
    bool user_modules_ = false;
    // Per function literal: the names its body reads or calls (what a closure copies).
    std::unordered_map<const ast::Expr*, std::vector<std::string_view>> free_names_;
    bool function_values_ = false;  // a literal was evaluated: calls look at variables first
    Loader files_;                                           // every parsed file, kept alive
    std::unordered_map<std::string, std::unique_ptr<Scope>> use_scopes_;  // by Loader::identity

    // -D overrides of top-level bindings.
    struct Define {
        std::string name;
        Value value;
        bool used = false;
    };
    std::vector<Define> defines_;

    // viewport.cpp: the main file's top-level $vpr, $vpt, $vpd, $vpf (or
    // -D ones; loc null) in binding order, and the default camera they make.
    struct ViewportVar {
        std::string_view name;
        Value value;
        const SourceLoc* loc;
    };
    std::vector<ViewportVar> viewport_;
    void note_viewport(std::string_view name, const Value& v, const SourceLoc* loc);
    void viewport_camera(const SourceLoc& top);

    ModuleState modules_;              // what built-in modules remember
    std::vector<Diagnostic> warnings_;
    // warn()'s fast way to a repeat: the warnings kept under a hash of their
    // place and message, and the calls each was last reached through (a
    // loop warns again through the same calls, so no notes are built).
    std::unordered_map<std::size_t, std::vector<std::size_t>> warning_index_;
    std::vector<std::vector<CallSite>> warning_calls_;
    // Past kMaxWarnings different warnings, the others are counted into one
    // last warning at the first of them (close_warnings writes its text).
    static constexpr std::size_t kMaxWarnings = 1000;
    std::uint64_t warnings_dropped_ = 0;
    std::string first_dropped_;
    void close_warnings();
    std::int64_t root_override_ = -1;  // the first `!` subtree
    std::size_t root_ghosts_[2] = {0, 0};  // the ghosts recorded inside it: [from, to)
    std::uint64_t exact_curves_ = 0;   // exact_curve(): how many, and the first
    SourceLoc first_exact_curve_{};

    std::vector<Diagnostic> errors_;
    void record_error(const SourceError& e);  // throws once kMaxErrors are kept
    [[noreturn]] void throw_errors();

    void parse_defines();
    friend struct DepthGuard;
    friend class ModuleCall;
};

}  // namespace kerf::eval

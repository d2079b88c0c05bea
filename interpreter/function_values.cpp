// Function literals (docs/language.md §6): `f = function (x) x * n;`. A
// literal's value is a Closure: it copies the bindings (and local function
// definitions) its body names from the scopes between it and its file, so
// it outlives the call or loop that made it; names of the file itself are
// looked up when the function runs (a top-level name bound below the
// literal is seen, as in OpenSCAD).
#include <algorithm>

#include "interpreter/evaluator.hpp"

namespace kerf::eval {
namespace {

void collect_names(const ast::Expr& e, std::vector<std::string_view>& out) {
    if (e.kind == ast::ExprKind::Ident || e.kind == ast::ExprKind::Call) out.push_back(e.text);
    for (const ast::ExprPtr& i : e.items)
        if (i) collect_names(*i, out);
    for (const auto* list : {&e.args, &e.bindings})
        for (const ast::Binding& b : *list)
            if (b.value) collect_names(*b.value, out);
}

Scope* file_scope(Scope& s) {
    Scope* f = &s;
    while (!f->file && f->parent) f = f->parent;
    return f;
}

}  // namespace

const Value* Evaluator::find_value(std::string_view name, Scope& s) {
    if (is_dollar(name)) {
        for (auto it = dyn_.rbegin(); it != dyn_.rend(); ++it)
            if (it->name == name) return &it->value;
        return nullptr;
    }
    for (Scope* sc = &s; sc; sc = sc->parent)
        if (VarSlot* v = sc->find_local(name); v && v->ready) return &v->value;
    return nullptr;
}

Value Evaluator::make_closure(const ast::Expr& e, Scope& s) {
    count_step(e.loc);
    function_values_ = true;
    auto [it, fresh] = free_names_.try_emplace(&e);
    if (fresh) {
        collect_names(*e.items[0], it->second);
        std::sort(it->second.begin(), it->second.end());
        it->second.erase(std::unique(it->second.begin(), it->second.end()), it->second.end());
    }
    Scope* file = file_scope(s);
    auto c = std::make_shared<Closure>(&e, file);
    // The names to copy: the body's, then those of each local function it
    // calls (that function runs in the closure's scope too).
    std::vector<std::string_view> names = it->second;
    for (std::size_t k = 0; k < names.size(); ++k) {
        std::string_view name = names[k];
        if (is_dollar(name) || c->env.find_local(name)) continue;  // `$`: read where the function runs
        bool param = false;
        for (const ast::Binding& p : e.bindings) param = param || p.name == name;
        if (param) continue;
        for (Scope* sc = &s; sc != file && sc; sc = sc->parent) {
            if (VarSlot* v = sc->find_local(name); v && v->ready) {
                c->env.add(VarSlot{v->name, v->value, v->loc, true});
                break;
            }
        }
        for (Scope* sc = &s; sc != file && sc; sc = sc->parent)
            for (const ast::Stmt* f : sc->functions) {
                if (f->name != name || std::find(c->env.functions.begin(), c->env.functions.end(), f) !=
                                           c->env.functions.end())
                    continue;
                c->env.functions.push_back(f);
                if (f->value) collect_names(*f->value, names);
                for (const ast::Binding& p : f->params)
                    if (p.value) collect_names(*p.value, names);
            }
    }
    return Value::function(std::move(c));
}

// `expr(args)`: a call of whatever value expr has.
Value Evaluator::apply(const ast::Expr& e, Scope& s) {
    Value f = eval(*e.items[0], s);
    // The name outlives the call: a kept warning's call stack refers to it.
    static const std::string kName = "function";
    if (f.is_function()) return call_closure(f, e.args, s, e.loc, kName);
    std::string message = std::string("cannot call ") + (f.is_undef() ? "undef" : std::string("a ") + f.type_name()) +
                          ", only a function";
    if (!lenient_) throw SourceError(e.loc, message);
    warn(e.loc, message);
    return Value();
}

}  // namespace kerf::eval

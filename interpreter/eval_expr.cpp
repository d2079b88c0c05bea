// Expressions: names, calls, list comprehensions, let/echo/assert, the
// evaluator's limits (operators, ranges and indexing: eval_ops.cpp).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>

#include "interpreter/builtins/builtins.hpp"
#include "interpreter/evaluator.hpp"
#include "interpreter/openscad_ops.hpp"
#include "interpreter/operators.hpp"

namespace kerf::eval {

struct Evaluator::DepthGuard {
    Evaluator& ev;
    DepthGuard(Evaluator& e, const SourceLoc& loc) : ev(e) {
        if (ev.depth_ + 1 > ev.call_depth_)
            throw SourceError(loc, "call depth limit " + std::to_string(ev.call_depth_) + " exceeded");
        ++ev.depth_;
        ev.count_step(loc);
    }
    ~DepthGuard() { --ev.depth_; }
};

void Evaluator::count_step(const SourceLoc& loc) {
    if (++steps_ > opt_.limits.steps)
        throw RunLimitError(loc, "evaluation step limit " + std::to_string(opt_.limits.steps) + " exceeded");
}

void Evaluator::count_iterations(std::uint64_t n, const SourceLoc& loc) {
    if (n > opt_.limits.loop_iterations || iterations_ + n > opt_.limits.loop_iterations)
        throw RunLimitError(loc, "loop iteration limit " + std::to_string(opt_.limits.loop_iterations) + " exceeded");
    iterations_ += n;
}

std::uint64_t Evaluator::iteration_count(Value& v, const SourceLoc& loc) {
    std::uint64_t n;
    if (v.is_range()) {
        n = v.as_range().size();
        // OpenSCAD runs no pass over a range it counts too many elements
        // in (a step of 0 among them), with its warning.
        if (lenient_)
            if (const std::uint32_t count = openscad_range_count(v.as_range()); count >= kOpenScadForCap) {
                warn(loc, "Bad range parameter in for statement: too many elements (" + std::to_string(count) + ")");
                n = 0;
            }
    } else if (v.is_list()) n = v.as_list().size();
    else if (v.is_string()) n = utf8_length(v.as_string());
    else if (lenient_) {  // OpenSCAD: undef runs no iteration, any other value one
        n = v.is_undef() ? 0 : 1;
        v = Value::list(n ? ValueList{v} : ValueList{});
    } else throw SourceError(loc, std::string("for: expected a range, a list or a string, got ") + v.type_name());
    count_iterations(n, loc);  // before building a list of characters
    if (v.is_string()) {
        // One string per character, as OpenSCAD iterates: the same
        // characters as len() counts and s[i] indexes (operators.hpp).
        ValueList chars;
        chars.reserve(n);
        for (std::string_view c : characters(v.as_string())) chars.push_back(Value::string(std::string(c)));
        v = Value::list(std::move(chars));
    }
    return n;
}

void Evaluator::list_limit(const SourceLoc& loc) const {
    throw SourceError(loc, "list size limit " + std::to_string(opt_.limits.list_elements) + " exceeded");
}

void Evaluator::push_element(ValueList& out, Value v, const SourceLoc& loc) {
    if (out.size() >= opt_.limits.list_elements) list_limit(loc);
    out.push_back(std::move(v));
}

// A name bound and ready in the nearest scope that has it: the loop in
// line, every other answer (a `$` name, one not ready, none) out of line.
Value Evaluator::lookup(const ast::Expr& e, Scope& s) {
    std::string_view name = e.text;
    if (!is_dollar(name))
        for (Scope* sc = &s; sc; sc = sc->parent)
            if (VarSlot* v = sc->find_local(name)) {
                if (v->ready) [[likely]] return v->value;
                break;
            }
    return lookup_slow(e, s);
}

Value Evaluator::lookup_slow(const ast::Expr& e, Scope& s) {
    std::string_view name = e.text;
    if (is_dollar(name)) {
        if (name == "$children") return Value(static_cast<double>(s.module ? s.module->child_count : 0));
        for (auto it = dyn_.rbegin(); it != dyn_.rend(); ++it)
            if (it->name == name) return it->value;
        // Tessellation settings and animation time: accepted, ignored.
        if (name == "$fn" || name == "$t") return Value(0);
        if (name == "$fa") return Value(12);
        if (name == "$fs") return Value(2);
        if (name == "$preview") return Value(false);
        // The viewport, as OpenSCAD 2021 has it when run from the command
        // line (`openscad -o x.echo`); a top-level binding of one places the
        // default camera (viewport.cpp).
        if (name == "$vpr" || name == "$vpt") return Value::list(ValueList{Value(0), Value(0), Value(0)});
        if (name == "$vpd") return Value(500);
        if (name == "$vpf") return Value(22.5);
        if (lenient_) return unknown_variable(e);
        throw SourceError(e.loc, "undefined name '" + e.text + "'" + did_you_mean(e.text, s, NameKind::Variable));
    }
    for (Scope* sc = &s; sc; sc = sc->parent) {
        if (VarSlot* v = sc->find_local(name)) {
            if (!v->ready) {
                if (v->failed) throw CascadeError(e.loc, "'" + e.text + "' has no value (its binding failed)");
                if (lenient_) continue;  // OpenSCAD: not bound here yet, so look outside
                throw SourceError(e.loc, "'" + e.text + "' is used before its definition at " + line_ref(e.loc, *v->loc));
            }
            return v->value;
        }
    }
    if (lenient_) return unknown_variable(e);
    throw SourceError(e.loc, "undefined name '" + e.text + "'" + did_you_mean(e.text, s, NameKind::Variable));
}

Value Evaluator::unknown_variable(const ast::Expr& e) {
    warn(e.loc, "Ignoring unknown variable '" + e.text + "'");
    return Value();
}

void Evaluator::bind(Scope& s, std::string_view name, Value v, const SourceLoc* loc) {
    if (is_dollar(name)) {
        dyn_.push_back(DynVar{name, std::move(v)});
        return;
    }
    s.add(VarSlot{name, std::move(v), loc, true});
}

// let (a = 1, b = a + 1): each binding sees the previous ones.
void Evaluator::bind_sequential(const std::vector<ast::Binding>& bindings, Scope& s, const char* what) {
    s.vars.reserve(s.vars.size() + bindings.size());
    for (const ast::Binding& b : bindings) {
        if (b.name.empty()) throw SourceError(b.loc, std::string(what) + ": expected name = value");
        if (VarSlot* prev = s.find_local(b.name)) {
            if (!lenient_)
                throw SourceError(b.loc, "'" + b.name + "' is already defined at " + line_ref(b.loc, *prev->loc));
            // OpenSCAD keeps the first and evaluates the second only to show it.
            Value ignored = b.value ? eval(*b.value, s) : Value();
            warn(b.loc, "Ignoring duplicate variable assignment " + b.name + " = " + to_repr(ignored));
            continue;
        }
        Value v = b.value ? eval(*b.value, s) : Value();
        bind(s, b.name, std::move(v), &b.loc);
    }
}

void Evaluator::do_echo(const std::vector<ast::Binding>& args, Scope& s, const SourceLoc& loc) {
    std::string line = "ECHO: ";
    bool first = true;
    for (const ast::Binding& a : args) {
        if (!first) line += ", ";
        first = false;
        if (!a.name.empty()) line += a.name + " = ";
        if (!a.value) {
            line += "undef";
            continue;
        }
        auto text = to_repr_bounded(eval(*a.value, s), opt_.limits.list_elements);
        if (!text)
            throw SourceError(a.loc, "echo: text longer than " + std::to_string(opt_.limits.list_elements) +
                                         " characters");
        line += *text;
    }
    echo_bytes_ += line.size() + 1;
    if (echo_bytes_ > opt_.limits.echo_bytes)
        throw SourceError(loc, "echo output limit " + std::to_string(opt_.limits.echo_bytes) + " bytes exceeded");
    if (opt_.echo) opt_.echo(line);
    else std::cerr << line << '\n';
}

void Evaluator::do_assert(const std::vector<ast::Binding>& args, Scope& s, const SourceLoc& loc) {
    const ast::Expr* cond = nullptr;
    const ast::Expr* msg = nullptr;
    std::size_t positional = 0;
    for (const ast::Binding& a : args) {
        std::string_view n = a.name;
        if (n.empty()) n = positional == 0 ? "condition" : positional == 1 ? "message" : "";
        if (a.name.empty()) ++positional;
        if (n == "condition") cond = a.value.get();
        else if (n == "message") msg = a.value.get();
        else if (n.empty()) throw SourceError(a.loc, "too many arguments for 'assert' (takes 2)");
        else throw SourceError(a.loc, "unknown argument '" + a.name + "' for 'assert'");
    }
    if (!cond) throw SourceError(loc, "assert: missing condition");
    if (eval(*cond, s).truthy()) return;
    if (msg) throw SourceError(loc, "assertion failed: " + to_str(eval(*msg, s)));
    throw SourceError(loc, "assertion failed");
}

const ast::Stmt* Evaluator::find_function(std::string_view name, Scope& s, Scope*& def_scope) {
    for (Scope* sc = &s; sc; sc = sc->parent) {
        for (const ast::Stmt* f : sc->functions)
            if (f->name == name) return def_scope = sc, f;
        for (Scope* used : sc->used)
            for (const ast::Stmt* f : used->functions)
                if (f->name == name) return def_scope = used, f;
    }
    return nullptr;
}

Value Evaluator::call_function(const ast::Expr& e, Scope& s) {
    std::string_view name = e.text;
    // OpenSCAD calls a variable holding a function before a function of
    // that name (only once a literal exists can a variable hold one).
    if (function_values_)
        if (const Value* v = find_value(name, s); v && v->is_function()) return call_closure(*v, e.args, s, e.loc, e.text);
    Scope* def_scope = nullptr;
    const ast::Stmt* def = find_function(name, s, def_scope);
    if (!def) return call_builtin(e, s);
    DepthGuard guard(*this, e.loc);
    DynRestore restore(dyn_);
    Scope callee(def_scope);
    callee.module = def_scope->module;
    if (def->self_tail_call < 0) def->self_tail_call = def->value && calls_itself_last(*def->value, def->name);
    return traced([&] {
        bind_params(def->params, e.args, def->name, s, callee, e.loc);
        if (!def->self_tail_call) return def->value ? eval(*def->value, callee) : Value();
        return run_body(*def, *def_scope, callee);
    });
}

// Whether e, in tail position, may call `name`: through ?:, let, echo and
// assert, as run_body follows them.
bool Evaluator::calls_itself_last(const ast::Expr& e, std::string_view name) {
    switch (e.kind) {
        case ast::ExprKind::Ternary:
            return calls_itself_last(*e.items[1], name) || calls_itself_last(*e.items[2], name);
        case ast::ExprKind::Let:
        case ast::ExprKind::Echo:
        case ast::ExprKind::Assert: return !e.items.empty() && e.items[0] && calls_itself_last(*e.items[0], name);
        case ast::ExprKind::Call: return e.text == name;
        default: return false;
    }
}

// A function's body, with OpenSCAD 2021's tail calls: through `?:`, `let`,
// `echo` and `assert`, a call of the function itself rebinds its parameters
// and loops instead of nesting, so `f(n - 1, acc + n)` recursion is not
// bound by the call depth (OpenSCAD's evaluate_function() does the same,
// and stops a chain at 1,000,000 calls). Only while the call has pushed no
// `$` variable: those belong to the call they were bound in.
Value Evaluator::run_body(const ast::Stmt& def, Scope& def_scope, Scope& callee) {
    const std::size_t dyn_entry = dyn_.size();
    const std::size_t calls_entry = calls_.size();  // the call's own note is the last
    // The lets passed on the way: the first on the stack (the common `let
    // (...) expr` body costs no allocation), any further ones on the heap.
    std::optional<Scope> first_let;
    std::vector<std::unique_ptr<Scope>> lets;
    std::uint64_t tail_calls = 0;
    Scope* s = &callee;
    const ast::Expr* body = def.value.get();
    while (body) {
        switch (body->kind) {
            case ast::ExprKind::Ternary: body = body->items[eval(*body->items[0], *s).truthy() ? 1 : 2].get(); continue;
            case ast::ExprKind::Let:
                if (!first_let) {
                    first_let.emplace(s);
                    s = &*first_let;
                } else {
                    lets.push_back(std::make_unique<Scope>(s));
                    s = lets.back().get();
                }
                bind_sequential(body->bindings, *s, "let");
                body = body->items.empty() ? nullptr : body->items[0].get();
                continue;
            case ast::ExprKind::Echo:
            case ast::ExprKind::Assert:
                if (body->kind == ast::ExprKind::Echo) do_echo(body->args, *s, body->loc);
                else do_assert(body->args, *s, body->loc);
                body = body->items.empty() ? nullptr : body->items[0].get();
                continue;
            case ast::ExprKind::Call: {
                if (body->text != def.name || dyn_.size() != dyn_entry) break;
                if (function_values_)
                    if (const Value* v = find_value(body->text, *s); v && v->is_function()) break;
                Scope* scope = nullptr;
                if (find_function(body->text, *s, scope) != &def) break;
                if (++tail_calls > opt_.limits.tail_calls)
                    throw SourceError(body->loc, "tail call limit " + std::to_string(opt_.limits.tail_calls) +
                                                     " exceeded ('" + def.name + "' calls itself without end?)");
                count_step(body->loc);
                Scope next(&def_scope);
                bind_params(def.params, body->args, def.name, *s, next, body->loc);
                calls_.resize(calls_entry);  // notes name the first call, not each pass
                callee.truncate(0);
                for (VarSlot& v : next.vars) callee.add(std::move(v));
                lets.clear();
                first_let.reset();
                s = &callee;
                body = def.value.get();
                continue;
            }
            default: break;
        }
        return eval(*body, *s);
    }
    return Value();
}

// A function value's call (function_values.cpp makes them).
Value Evaluator::call_closure(const Value& f, const std::vector<ast::Binding>& args, Scope& caller,
                              const SourceLoc& loc, const std::string& name) {
    Value keep = f;  // the closure lives while it runs, even if rebound
    const Closure& c = keep.as_function();
    DepthGuard guard(*this, loc);
    DynRestore restore(dyn_);
    Scope callee(&c.env);
    return traced([&] {
        bind_params(c.literal->bindings, args, name, caller, callee, loc);
        return eval(*c.literal->items[0], callee);
    });
}

Value Evaluator::call_builtin(const ast::Expr& e, Scope& s) {
    if (e.text == "dxf_dim" || e.text == "dxf_cross") return call_dxf_function(e, s);
    const Builtin* fn = find_builtin(e.text);
    if (!fn) {
        if (!lenient_)
            throw SourceError(e.loc, "undefined function '" + e.text + "'" + did_you_mean(e.text, s, NameKind::Function));
        warn(e.loc, "Ignoring unknown function '" + e.text + "'");
        return Value();
    }
    count_step(e.loc);
    Value small[4];
    std::vector<Value> many;
    Value* argv = small;
    if (e.args.size() > 4) {
        many.resize(e.args.size());
        argv = many.data();
    }
    for (std::size_t i = 0; i < e.args.size(); ++i) {
        const ast::Binding& a = e.args[i];
        if (!a.name.empty()) check_builtin_name(*fn, a, i, e.args.size());
        argv[i] = a.value ? eval(*a.value, s) : Value();
    }
    // A built-in that walks a list argument (max, min, norm, search,
    // lookup, ...) costs its top-level length as elements, and one that
    // walks a string (len, ord, search, ...) one element per 16 bytes (so a
    // step per 256 bytes, count_work's 16 elements a step); not those that
    // only look at a type or a list's length, nor concat and str (charged
    // by what they make). What a built-in walks beyond that (the pairs
    // search compares) it tallies in ctx.work (WorkTally::walked).
    static constexpr std::string_view kMakers[] = {"concat", "str"};
    static constexpr std::string_view kTypeTests[] = {"is_list", "is_num",    "is_bool",
                                                      "is_string", "is_undef", "is_function"};
    auto among = [&](const auto& names) { return std::find(std::begin(names), std::end(names), e.text) != std::end(names); };
    std::uint64_t walked = 0;
    if (!among(kMakers) && !among(kTypeTests))
        for (std::size_t i = 0; i < e.args.size(); ++i) {
            if (argv[i].is_list() && e.text != "len") walked += argv[i].as_list().size();
            if (argv[i].is_string()) walked += argv[i].as_string().size() / 16;
        }
    count_work(walked, e.loc);
    WorkTally work{0, work_cap()};
    std::vector<std::string> said;
    BuiltinContext ctx{e.loc, opt_.limits.list_elements, module_stack_, lenient_, &said, &work};
    auto run = [&] {
        try {
            return fn->fn(std::span<const Value>(argv, e.args.size()), ctx);
        } catch (const WorkCapReached&) {
            count_work(work.walked, e.loc);  // past the limit: throws
            throw;
        }
    };
    if (!lenient_) {
        Value v = run();
        count_work(work.walked, e.loc);
        count_made(v, e.loc);
        return v;
    }
    Value v;
    try {
        v = run();
        for (std::string& m : said) warn(e.loc, std::move(m));
    } catch (const SoftError& err) {
        count_work(work.walked, e.loc);
        warn(err.diagnostic().loc, err.diagnostic().message);
        return Value();
    }
    count_work(work.walked, e.loc);
    count_made(v, e.loc);
    return v;
}

// A built-in's list or string result, or an operator's lists, is work no
// other count sees: concat() or str() growing an accumulator through a
// tail-recursive function copies it whole on every pass (quadratic in the
// passes), `v + v` on a long list costs its length each pass, and the
// tail-call limit (10^6 passes) alone would let either run for hours. So
// 16 elements (or 256 bytes) made or compared cost one step, about what
// copying them takes against a call: such a chain ends at the step limit
// within seconds, while building a list of 50,000 elements one concat at a
// time still fits the default.
void Evaluator::count_made(const Value& v, const SourceLoc& loc) {
    count_work(v.is_list() ? v.as_list().size() : v.is_string() ? v.as_string().size() / 16 : 0, loc);
}

// The elements count_work takes before the step limit is reached: a
// built-in's or an operator's loop stops there (WorkCapReached).
std::uint64_t Evaluator::work_cap() const {
    const std::uint64_t steps_left = opt_.limits.steps - std::min(steps_, opt_.limits.steps);
    return steps_left < UINT64_MAX / 32 ? (steps_left + 1) * 16 : UINT64_MAX;
}

void Evaluator::count_work(std::uint64_t elements, const SourceLoc& loc) {
    const std::uint64_t n = elements / 16;
    if (n == 0) return;
    steps_ += n;
    if (steps_ > opt_.limits.steps)
        throw RunLimitError(loc, "evaluation step limit " + std::to_string(opt_.limits.steps) + " exceeded");
}

// OpenSCAD takes a built-in's arguments in order, whatever their names, so
// a name is only documentation: `pow(base = 2, exponent = 3)` is accepted,
// a name that is not the parameter at its position is an error (a warning
// in the OpenSCAD dialect, where the argument is still taken in order, as
// OpenSCAD does) rather than silently meaning something else.
void Evaluator::check_builtin_name(const Builtin& fn, const ast::Binding& a, std::size_t i, std::size_t count) {
    std::string_view param = builtin_param(fn, i, count);
    if (a.name == param) return;
    std::string message = param.empty() ? "'" + std::string(fn.name) + "' takes no argument named '" + a.name + "'"
                                        : "'" + std::string(fn.name) + "': argument " + std::to_string(i + 1) +
                                              " is '" + std::string(param) + "', not '" + a.name + "'";
    if (!lenient_) throw SourceError(a.loc, message + " (built-in arguments are taken in order)");
    warn(a.loc, message + "; taken in order, as OpenSCAD does");
}

void Evaluator::expand_for(const ast::Expr& e, std::size_t k, Scope& loop, ValueList& out) {
    const ast::Binding& b = e.bindings[k];
    if (b.name.empty() || !b.value) throw SourceError(b.loc, "for: expected name = range or list");
    Value seq = eval(*b.value, loop);
    std::uint64_t n = iteration_count(seq, b.loc);
    bool dollar = is_dollar(b.name);
    std::size_t slot = dollar ? dyn_.size() : loop.vars.size();
    if (dollar) dyn_.push_back(DynVar{b.name, Value()});
    else loop.add(VarSlot{b.name, Value(), &b.loc, true});
    for (std::uint64_t i = 0; i < n; ++i) {
        count_step(b.loc);
        Value item = seq.is_range() ? Value(seq.as_range().at(i)) : seq.as_list()[i];
        if (dollar) dyn_[slot].value = std::move(item);
        else loop.vars[slot].value = std::move(item);
        if (k + 1 < e.bindings.size()) expand_for(e, k + 1, loop, out);
        else expand_element(*e.items[0], loop, out);
    }
    if (dollar) dyn_.resize(slot);
    else loop.truncate(slot);
}

// `for (init; cond; incr) element`, as OpenSCAD runs it: init binds in
// order, then while cond holds, the element, then incr evaluated in order
// (each sees the ones before it) and applied over the loop's variables; a
// name only incr binds joins them. Every pass counts one iteration.
void Evaluator::expand_for_c(const ast::Expr& e, Scope& s, ValueList& out) {
    DynRestore restore(dyn_);
    Scope loop(&s);
    bind_sequential(e.bindings, loop, "for");
    const std::size_t dyn_loop = dyn_.size();
    while (eval(*e.items[0], loop).truthy()) {
        count_iterations(1, e.loc);
        count_step(e.loc);
        expand_element(*e.items[1], loop, out);
        const std::size_t dyn_before = dyn_.size();
        Scope next(&loop);
        bind_sequential(e.args, next, "for");
        for (VarSlot& v : next.vars) {
            if (VarSlot* old = loop.find_local(v.name)) old->value = std::move(v.value);
            else loop.add(std::move(v));
        }
        // `$` names went to the dynamic stack: replace the loop's earlier
        // entries instead of growing it by one per pass.
        std::size_t kept = dyn_before;
        for (std::size_t i = dyn_before; i < dyn_.size(); ++i) {
            std::size_t j = dyn_loop;
            while (j < dyn_before && dyn_[j].name != dyn_[i].name) ++j;
            if (j < dyn_before) dyn_[j].value = std::move(dyn_[i].value);
            else dyn_[kept++] = std::move(dyn_[i]);
        }
        dyn_.resize(kept);
    }
}

void Evaluator::expand_element(const ast::Expr& e, Scope& s, ValueList& out) {
    switch (e.kind) {
        case ast::ExprKind::ListFor: {
            DynRestore restore(dyn_);
            Scope loop(&s);
            loop.vars.reserve(e.bindings.size());
            for (std::size_t i = 0; i < e.bindings.size(); ++i)
                for (std::size_t j = 0; j < i; ++j)
                    if (e.bindings[i].name == e.bindings[j].name)
                        throw SourceError(e.bindings[i].loc, "'" + e.bindings[i].name + "' is already defined at " +
                                                                 line_ref(e.bindings[i].loc, e.bindings[j].loc));
            if (!e.bindings.empty()) expand_for(e, 0, loop, out);
            return;
        }
        case ast::ExprKind::ListForC: expand_for_c(e, s, out); return;
        case ast::ExprKind::ListEach: {
            // OpenSCAD: a list, range or string is spliced, undef adds
            // nothing, any other value is added as it is.
            ValueList inner;
            expand_element(*e.items[0], s, inner);
            for (Value& v : inner) {
                if (v.is_undef()) continue;
                if (!v.is_list() && !v.is_range() && !v.is_string()) {
                    push_element(out, std::move(v), e.loc);
                    continue;
                }
                std::uint64_t n = iteration_count(v, e.loc);
                for (std::uint64_t i = 0; i < n; ++i)
                    push_element(out, v.is_range() ? Value(v.as_range().at(i)) : v.as_list()[i], e.loc);
            }
            return;
        }
        case ast::ExprKind::ListIf:
            if (eval(*e.items[0], s).truthy()) expand_element(*e.items[1], s, out);
            else if (e.items.size() > 2) expand_element(*e.items[2], s, out);
            return;
        case ast::ExprKind::ListLet: {
            DynRestore restore(dyn_);
            Scope ls(&s);
            bind_sequential(e.bindings, ls, "let");
            expand_element(*e.items[0], ls, out);
            return;
        }
        default: push_element(out, eval(e, s), e.loc);
    }
}

thread_local const char* stack_floor = nullptr;

namespace {
bool is_generator(ast::ExprKind k) {
    using K = ast::ExprKind;
    return k == K::ListFor || k == K::ListForC || k == K::ListIf || k == K::ListLet || k == K::ListEach;
}
}  // namespace

// The dispatch alone, its cases that need a frame of their own out of line:
// one function for every kind made each call, a number literal or a name,
// pay the prologue and epilogue of the largest case (callee-saved
// registers, a budget, handlers): a third of evaluating `(i + 0.5) * 0.2`
// (docs/performance.md, "The interpreter's per-call costs").
Value Evaluator::eval_node(const ast::Expr& e, Scope& s) {
    using K = ast::ExprKind;
    char probe;
    if (stack_floor && &probe < stack_floor)
        throw SourceError(e.loc, "evaluation nested too deeply (stack exhausted; lower the call depth limit)");
    switch (e.kind) {
        case K::Number: return Value(e.number);
        case K::String: return Value::string(e.text);
        case K::Bool: return Value(e.number != 0);
        case K::Undef: return Value();
        case K::Ident: return lookup(e, s);
        case K::List: return eval_list(e, s);
        case K::Range: return eval_range(e, s);
        case K::Unary: return eval_unary(e, s);
        case K::Binary: return eval_binary(e, s);
        case K::Ternary: return eval(*e.items[eval(*e.items[0], s).truthy() ? 1 : 2], s);
        case K::Index: return eval_index(e, s);
        case K::Member: return eval_member(e, s);
        case K::Call: return call_function(e, s);
        case K::Function: return make_closure(e, s);
        case K::Apply: return apply(e, s);
        case K::Let: return eval_let(e, s);
        case K::Echo:
            do_echo(e.args, s, e.loc);
            return e.items.empty() || !e.items[0] ? Value() : eval(*e.items[0], s);
        case K::Assert:
            do_assert(e.args, s, e.loc);
            return e.items.empty() || !e.items[0] ? Value() : eval(*e.items[0], s);
        case K::ListFor:
        case K::ListForC:
        case K::ListEach:
        case K::ListIf:
        case K::ListLet: throw SourceError(e.loc, "a list generator is only allowed inside [ ]");
    }
    throw SourceError(e.loc, "unknown expression");
}

Value Evaluator::eval_list(const ast::Expr& e, Scope& s) {
    ValueList out;
    out.reserve(e.items.size());
    for (const ast::ExprPtr& item : e.items) {
        // A plain element (most are: `[x, y, z]`) is evaluated into place,
        // as expand_element's default case does, without its calls and moves.
        if (is_generator(item->kind)) {
            expand_element(*item, s, out);
            continue;
        }
        Value v = eval(*item, s);  // evaluated before the limit is checked, as push_element's argument was
        if (out.size() >= opt_.limits.list_elements) [[unlikely]]
            list_limit(item->loc);
        out.push_back(std::move(v));
    }
    return Value::list(std::move(out));
}

Value Evaluator::eval_let(const ast::Expr& e, Scope& s) {
    DynRestore restore(dyn_);
    Scope ls(&s);
    bind_sequential(e.bindings, ls, "let");
    return e.items.empty() ? Value() : eval(*e.items[0], ls);
}

}  // namespace kerf::eval

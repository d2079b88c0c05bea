// Statements: blocks and their bindings, modules and children(), for/let/
// echo/assert/if, include and use.
#include <optional>
#include <strings.h>
#include <unordered_map>

#include "grammar/parser.hpp"
#include "interpreter/evaluator.hpp"
#include "interpreter/modules/module_call.hpp"
#include "interpreter/openscad_ops.hpp"
#include "interpreter/text/font.hpp"

namespace kerf::eval {

namespace {

// Names bound twice in one block (by hash: a file may bind 100,000 names).
class UniqueNames {
public:
    explicit UniqueNames(std::size_t expected) { first_.reserve(expected); }
    // Appends st to seen. A name already there is an error, or, in the
    // OpenSCAD dialect, st takes the earlier one's place (OpenSCAD's parser
    // does the same), which is returned.
    const ast::Stmt* add(std::vector<const ast::Stmt*>& seen, const ast::Stmt& st, const char* what, bool lenient) {
        auto [it, fresh] = first_.emplace(st.name, seen.size());
        if (fresh) {
            seen.push_back(&st);
            return nullptr;
        }
        const ast::Stmt* earlier = seen[it->second];
        if (!lenient)
            throw SourceError(st.loc, std::string(what) + "'" + st.name + "' is already defined at " +
                                          line_ref(st.loc, earlier->loc));
        seen[it->second] = &st;
        return earlier;
    }

private:
    std::unordered_map<std::string_view, std::size_t> first_;
};

// OpenSCAD's Expression::isLiteral(): a literal, or a sign, list or range
// of literals (what its "overwritten with a literal" warning looks at).
bool is_literal(const ast::Expr& e) {
    switch (e.kind) {
        case ast::ExprKind::Number:
        case ast::ExprKind::String:
        case ast::ExprKind::Bool:
        case ast::ExprKind::Undef: return true;
        case ast::ExprKind::Unary:
        case ast::ExprKind::List:
        case ast::ExprKind::Range:
            for (const ast::ExprPtr& i : e.items)
                if (!i || !is_literal(*i)) return false;
            return true;
        default: return false;
    }
}

// `use <f.ttf>` names a font, not a script (OpenSCAD's FileModule::registerUse).
bool is_font_file(const std::string& path) {
    const std::size_t n = path.size();
    return n >= 4 && (strcasecmp(path.c_str() + n - 4, ".ttf") == 0 || strcasecmp(path.c_str() + n - 4, ".otf") == 0);
}

}  // namespace

// ---------------------------------------------------------------- files

void Evaluator::flatten(const std::vector<ast::StmtPtr>& stmts, std::vector<const ast::Stmt*>& out) {
    for (const ast::StmtPtr& sp : stmts) {
        const ast::Stmt& st = *sp;
        // OpenSCAD's parser puts a bare `{ ... }`'s statements in the
        // enclosing block: its bindings are the block's own (`f = 2;` in it
        // replaces the outer f, with the overwrite warning).
        if (lenient_ && st.kind == ast::StmtKind::Block && st.modifier == ast::Modifier::None) {
            flatten(st.body, out);
            continue;
        }
        if (st.kind != ast::StmtKind::Include) {
            out.push_back(&st);
            continue;
        }
        const std::string path = find_library(st);
        if (path.empty()) continue;
        if (lenient_) {
            // OpenSCAD's chain of spellings (Loader::spelled_includes): one
            // on it is as if the file were not there; every other spelling
            // of the file expands it again, each expansion a counted step.
            const std::string key = Loader::spelling(st.loc.file ? st.loc.file->path : path, st.name);
            auto& chain = files_.spelled_includes;
            if (std::find(chain.begin(), chain.end(), key) != chain.end()) {
                warn(st.loc, "Can't open include file '" + st.name + "'.");
                continue;
            }
            const std::string file = Loader::identity(path);
            auto& open = files_.spelled_files;
            if (files_.includes.contains(path) || std::find(open.begin(), open.end(), file) != open.end())
                if (++files_.repeated_includes > Loader::kMaxRepeatedIncludes)
                    throw RunLimitError(st.loc, "include: more than " + std::to_string(Loader::kMaxRepeatedIncludes) +
                                                    " expansions of files already being included under another spelling ('" +
                                                    st.name + "' here)");
            count_step(st.loc);
            chain.push_back(chain.empty() ? file : key);
            open.push_back(file);
            struct Pop {
                std::vector<std::string>& chain;
                std::vector<std::string>& open;
                ~Pop() {
                    chain.pop_back();
                    open.pop_back();
                }
            } pop{chain, open};
            flatten(files_.load(path, st.loc).stmts, out);
            continue;
        }
        ChainGuard on_chain(files_.includes, path, st.loc);
        flatten(files_.load(path, st.loc).stmts, out);
    }
}

// A file named by include or use that is nowhere: an error, or in the
// OpenSCAD dialect OpenSCAD 2021's warning, and the run goes on without it
// (its modules and functions then warn as unknown where they are called).
std::string Evaluator::find_library(const ast::Stmt& st) {
    if (!lenient_) return files_.resolve(st.name, st.loc);
    std::string path = files_.find(st.name, st.loc);
    if (path.empty())
        warn(st.loc, st.kind == ast::StmtKind::Include ? "Can't open include file '" + st.name + "'."
                                                       : "Can't open library '" + st.name + "'.");
    return path;
}

Scope* Evaluator::load_use(const ast::Stmt& st) {
    const std::string path = find_library(st);
    if (path.empty()) return nullptr;
    if (is_font_file(path)) {  // OpenSCAD: the font's families become usable by text()
        if (!text::register_font_file(path)) {
            if (!lenient_) throw SourceError(st.loc, "cannot read the font file '" + st.name + "'");
            warn(st.loc, "Can't read font with path '" + st.name + "'");
        }
        return nullptr;
    }
    const std::string key = Loader::identity(path);
    auto it = use_scopes_.find(key);
    if (it != use_scopes_.end()) return it->second.get();
    ChainGuard on_chain(files_.uses, path, st.loc);
    const ast::Program& prog = files_.load(path, st.loc);
    // The used file's includes start a chain of their own.
    std::vector<std::string> outer_includes, outer_spelled, outer_files;
    files_.includes.swap(outer_includes);
    files_.spelled_includes.swap(outer_spelled);
    files_.spelled_files.swap(outer_files);
    struct Restore {
        Loader& files;
        std::vector<std::string>& saved;
        std::vector<std::string>& saved_spelled;
        std::vector<std::string>& saved_files;
        ~Restore() {
            files.includes.swap(saved);
            files.spelled_includes.swap(saved_spelled);
            files.spelled_files.swap(saved_files);
        }
    } restore{files_, outer_includes, outer_spelled, outer_files};
    ChainGuard in_file(files_.includes, path, st.loc);
    auto scope = std::make_unique<Scope>(&root_);
    scope->file = true;
    bind_block(prepare(prog.stmts), *scope, false);  // its solids are not used
    Scope* raw = scope.get();
    use_scopes_[key] = std::move(scope);
    return raw;
}

// ---------------------------------------------------------------- blocks

const BlockInfo& Evaluator::prepare(const std::vector<ast::StmtPtr>& stmts) {
    if (&stmts == last_block_) return *last_info_;
    auto it = blocks_.find(&stmts);
    if (it != blocks_.end()) {
        last_block_ = &stmts;
        last_info_ = &it->second;
        return it->second;
    }
    // The main file is the first link of its include chain.
    std::optional<ChainGuard> main_file;
    if (files_.includes.empty() && !stmts.empty() && stmts[0]->loc.file)
        main_file.emplace(files_.includes, stmts[0]->loc.file->path, stmts[0]->loc);
    std::vector<const ast::Stmt*> flat;
    BlockInfo info;
    {
        flatten(stmts, flat);
        UniqueNames names(flat.size()), functions(0), modules(0);  // three namespaces, as in OpenSCAD
        for (const ast::Stmt* st : flat) {
            switch (st->kind) {
                case ast::StmtKind::Assign:
                    if (const ast::Stmt* earlier = names.add(info.assigns, *st, "", lenient_))
                        warn_overwritten(*earlier, *st);
                    break;
                // OpenSCAD: a later definition replaces an earlier one, silently.
                case ast::StmtKind::FunctionDef: functions.add(info.functions, *st, "function ", lenient_); break;
                case ast::StmtKind::ModuleDef: modules.add(info.modules, *st, "module ", lenient_); break;
                case ast::StmtKind::Use:
                    if (Scope* used = load_use(*st)) info.used.push_back(used);
                    break;
                case ast::StmtKind::Empty:
                case ast::StmtKind::Include: break;
                default: info.children.push_back(st);
            }
        }
    }
    info.needs_scope = !info.assigns.empty() || !info.functions.empty() || !info.modules.empty() || !info.used.empty();
    user_modules_ = user_modules_ || !info.modules.empty();
    return blocks_.emplace(&stmts, std::move(info)).first->second;
}

// OpenSCAD's warning for a binding replaced by a later one: in the main
// file always, within one other file when the lines differ, and when an
// included file replaces the main file's; never when the main file (or
// another file) replaces an included file's, the usual configuration idiom.
void Evaluator::warn_overwritten(const ast::Stmt& earlier, const ast::Stmt& later) {
    const std::string prev = earlier.loc.file ? earlier.loc.file->path : std::string();
    const std::string cur = later.loc.file ? later.loc.file->path : std::string();
    std::string head = later.name + " was assigned on line " + std::to_string(earlier.loc.line);
    if (prev == main_path_ && cur == main_path_) warn(later.loc, head + " but was overwritten");
    else if (prev == cur ? earlier.loc.line != later.loc.line : prev == main_path_)
        warn(later.loc, head + " of " + prev + " but was overwritten");
}

namespace {

// The element limits bound each list, not a list of many large lists: memory
// itself is the last limit (the CLI caps it). Running out inside a top-level
// statement is reported at that statement; by the time the handler runs,
// the statement's values are freed, so reporting is safe.
template <class F>
decltype(auto) memory_guarded(bool top_level, const SourceLoc& loc, F&& f) {
    if (!top_level) return f();
    try {
        return f();
    } catch (const std::bad_alloc&) {
        throw RunLimitError(loc, "out of memory evaluating this statement");
    }
}

}  // namespace

void Evaluator::bind_block(const BlockInfo& info, Scope& scope, bool top_level) {
    scope.functions = info.functions;
    scope.modules = info.modules;
    scope.used = info.used;
    scope.vars.reserve(info.assigns.size());
    for (const ast::Stmt* a : info.assigns)
        if (!is_dollar(a->name)) scope.add(VarSlot{a->name, Value(), &a->loc, false});
    std::size_t slot = 0;
    for (const ast::Stmt* a : info.assigns) {
        Value v;
        Define* def = nullptr;
        if (top_level)
            for (Define& d : defines_)
                if (d.name == a->name) def = &d;
        if (def) {
            def->used = true;
            v = def->value;
        } else if (a->value && !top_level) {
            v = eval(*a->value, scope);
        } else if (a->value) {
            try {
                v = memory_guarded(top_level, a->loc, [&] { return eval(*a->value, scope); });
            } catch (const RunLimitError&) {
                throw;
            } catch (const SourceError& e) {
                // Reported; the name stays unbound, and what reads it is
                // given up without a second error (CascadeError).
                if (!dynamic_cast<const CascadeError*>(&e)) record_error(e);
                if (!is_dollar(a->name)) scope.vars[slot++].failed = true;
                continue;
            }
        }
        if (is_dollar(a->name)) {
            if (top_level) note_viewport(a->name, v, &a->loc);
            dyn_.push_back(DynVar{a->name, std::move(v)});
        } else {
            scope.vars[slot].value = std::move(v);
            scope.vars[slot].ready = true;
            ++slot;
        }
    }
}

void Evaluator::eval_block(const std::vector<ast::StmtPtr>& stmts, Scope& s, bool top_level) {
    const BlockInfo& info = prepare(stmts);
    DynRestore restore(dyn_);
    std::optional<Scope> own;
    if (info.needs_scope) {
        own.emplace(&s);
        own->file = top_level;  // the main file's scope lives through the run
        bind_block(info, *own, top_level);
    }
    Scope& scope = own ? *own : s;
    if (!top_level) {
        for (const ast::Stmt* c : info.children) eval_stmt(*c, scope, false);
        return;
    }
    for (const ast::Stmt* c : info.children) {
        const std::size_t mark = out_.mark();
        try {
            memory_guarded(true, c->loc, [&] { eval_stmt(*c, scope, true); });
        } catch (const RunLimitError&) {
            throw;
        } catch (const SourceError& e) {
            if (!dynamic_cast<const CascadeError*>(&e)) record_error(e);
            out_.pending.resize(mark);  // what the failed statement made is dropped
        }
    }
}

// ---------------------------------------------------------------- calls

void Evaluator::bind_params(const std::vector<ast::Binding>& params, const std::vector<ast::Binding>& args,
                            const std::string& callee, Scope& caller, Scope& scope, const SourceLoc& loc) {
    (void)loc;
    constexpr std::size_t inline_params = 8;
    Value given_small[inline_params];
    bool have_small[inline_params] = {};
    std::vector<Value> given_big;
    std::vector<char> have_big;
    Value* given = given_small;
    bool* have = have_small;
    std::unique_ptr<bool[]> have_heap;
    if (params.size() > inline_params) {
        given_big.resize(params.size());
        have_heap = std::make_unique<bool[]>(params.size());
        given = given_big.data();
        have = have_heap.get();
    }
    std::size_t positional = 0;
    std::size_t dyn_start = dyn_.size();
    std::vector<std::pair<const ast::Binding*, Value>> extra;  // OpenSCAD binds them too
    for (const ast::Binding& a : args) {
        Value v = a.value ? eval(*a.value, caller) : Value();
        std::size_t i;
        if (a.name.empty()) {
            if (positional >= params.size()) {
                if (lenient_) {  // OpenSCAD drops the extra arguments
                    warn(a.loc, "Too many unnamed arguments supplied");
                    continue;
                }
                throw SourceError(a.loc, "too many arguments for '" + callee + "' (takes " +
                                             std::to_string(params.size()) + ")");
            }
            i = positional++;
        } else {
            i = params.size();
            for (std::size_t j = 0; j < params.size(); ++j)
                if (params[j].name == a.name) i = j;
            if (i == params.size()) {
                // Any `$` variable may be passed to a module, as in OpenSCAD.
                if (is_dollar(a.name)) {
                    dyn_.push_back(DynVar{a.name, std::move(v)});
                    continue;
                }
                if (lenient_) {  // OpenSCAD binds it in the call anyway, after the parameters
                    warn(a.loc, "variable " + a.name + " not specified as parameter");
                    extra.emplace_back(&a, std::move(v));
                    continue;
                }
                throw SourceError(a.loc, "unknown argument '" + a.name + "' for '" + callee + "'");
            }
        }
        if (have[i] && lenient_) warn(a.loc, "argument " + params[i].name + " supplied more than once");  // the last counts
        else if (have[i]) throw SourceError(a.loc, "argument '" + params[i].name + "' given twice to '" + callee + "'");
        have[i] = true;
        given[i] = std::move(v);
    }
    (void)dyn_start;
    calls_.push_back(CallSite{callee, &loc});  // defaults and the body run in the call
    scope.vars.reserve(params.size());
    for (std::size_t i = 0; i < params.size(); ++i) {
        const ast::Binding& p = params[i];
        Value v;
        if (have[i]) v = std::move(given[i]);
        else if (p.value) v = eval(*p.value, scope);  // defaults see earlier parameters
        bind(scope, p.name, std::move(v), &p.loc);
    }
    for (auto& [a, v] : extra) {
        if (VarSlot* twice = scope.find_local(a->name)) twice->value = std::move(v);  // the last counts
        else bind(scope, a->name, std::move(v), &a->loc);
    }
}

void Evaluator::call_module(const ast::Stmt& def, Scope& def_scope, const ast::Stmt& call, Scope& s) {
    if (depth_ + 1 > call_depth_)
        throw SourceError(call.loc, "call depth limit " + std::to_string(call_depth_) + " exceeded");
    ++depth_;
    struct Dec {
        std::uint64_t& d;
        ~Dec() { --d; }
    } dec{depth_};
    DynRestore restore(dyn_);
    ModuleFrame frame{&call.body, &s, prepare(call.body).children.size(), calls_.size()};
    Scope callee(&def_scope);
    callee.module = &frame;
    traced([&] {
        bind_params(def.params, call.args, def.name, s, callee, call.loc);
        // OpenSCAD's module stack: user modules only, and children() run
        // with it unchanged (their modules see the one that passed them on).
        module_stack_.push_back(def.name);
        struct PopModule {
            std::vector<std::string_view>& m;
            ~PopModule() { m.pop_back(); }
        } pop{module_stack_};
        bind(callee, "$parent_modules", Value(static_cast<double>(module_stack_.size())), nullptr);
        if (lenient_)  // OpenSCAD's ModuleContext::initializeModule()
            for (const ast::Stmt* a : prepare(def.body).assigns)
                if (a->value && is_literal(*a->value) && callee.find_local(a->name))
                    warn(a->loc, "Module " + def.name + ": Parameter " + a->name + " is overwritten with a literal");
        std::size_t mark = out_.mark();
        eval_block(def.body, callee, false);
        out_.group(mark, call.loc);
    });
}

void Evaluator::stmt_children(const ast::Stmt& st, Scope& s) {
    const ModuleFrame* frame = s.module;
    if (!frame && lenient_) return warn(st.loc, "children() outside a module makes nothing");  // OpenSCAD: silently
    if (!frame) throw SourceError(st.loc, "children() is only allowed inside a module");
    if (st.args.size() > 1 && lenient_) warn(st.args[1].loc, "children() takes one argument: the others are ignored");
    else if (st.args.size() > 1) throw SourceError(st.args[1].loc, "too many arguments for 'children' (takes 1)");
    if (!st.args.empty() && !st.args[0].name.empty() && st.args[0].name != "index")
        throw SourceError(st.args[0].loc, "unknown argument '" + st.args[0].name + "' for 'children'");
    const BlockInfo& info = prepare(*frame->children);
    std::vector<std::size_t> picks;
    if (st.args.empty()) {
        for (std::size_t i = 0; i < info.children.size(); ++i) picks.push_back(i);
    } else {
        Value v = eval(*st.args[0].value, s);
        // OpenSCAD's answers (its ControlModule::getChild): a child it cannot
        // pick is nothing, with its warning.
        auto bad_type = [&](const Value& x) {
            warn(st.loc, "Bad parameter type (" + to_repr(x) + ") for children, only accept: empty, number, vector, range");
        };
        auto pick = [&](const Value& x) {
            double d = x.is_number() ? x.as_number() : 0;
            if (lenient_) {
                if (!x.is_number()) return bad_type(x);
                d = std::trunc(d);
                if (!(d >= 0)) return warn(st.loc, "Negative children index (" + format_number(d) + ") not allowed");
            } else if (!x.is_number() || d != std::floor(d)) {
                throw SourceError(st.loc, std::string("children: index must be an integer, got ") +
                                              (x.is_number() ? format_number(d) : x.type_name()));
            }
            if (d < 0 || d >= static_cast<double>(info.children.size())) {
                if (lenient_) {  // OpenSCAD: that child is nothing
                    warn(st.loc, "Children index (" + format_number(d) + ") out of bounds (" +
                                     std::to_string(info.children.size()) + " children)");
                    return;
                }
                throw SourceError(st.loc, "children: index " + format_number(d) + " out of range (" +
                                              std::to_string(info.children.size()) + " children)");
            }
            picks.push_back(static_cast<std::size_t>(d));
        };
        if (v.is_number()) pick(v);
        else if (v.is_list()) for (const Value& x : v.as_list()) pick(x);
        else if (v.is_range()) {
            if (const std::uint32_t count = openscad_range_count(v.as_range()); lenient_ && count >= kOpenScadChildrenCap)
                return warn(st.loc, "Bad range parameter for children: too many elements (" + std::to_string(count) + ")");
            std::uint64_t n = v.as_range().size();
            count_iterations(n, st.loc);
            for (std::uint64_t i = 0; i < n; ++i) pick(Value(v.as_range().at(i)));
        } else if (lenient_) return bad_type(v);
        else throw SourceError(st.loc, std::string("children: index must be a number, list or range, got ") + v.type_name());
    }
    std::size_t mark = out_.mark();
    DynRestore restore(dyn_);
    // The children run where the module was called: the calls inside the
    // module are not theirs (for notes and parent_module), until they end.
    std::vector<CallSite> inner(calls_.begin() + static_cast<std::ptrdiff_t>(frame->calls), calls_.end());
    calls_.resize(frame->calls);
    struct Back {
        std::vector<CallSite>& calls;
        std::vector<CallSite>& inner;
        std::size_t size;
        ~Back() {
            calls.resize(size);
            calls.insert(calls.end(), inner.begin(), inner.end());
        }
    } back{calls_, inner, frame->calls};
    try {
        Scope cs(frame->caller);
        Scope* where = frame->caller;
        if (info.needs_scope) {
            bind_block(info, cs, false);
            where = &cs;
        }
        for (std::size_t i : picks) eval_stmt(*info.children[i], *where, false);
    } catch (SourceError& e) {
        if (!e.has_call_notes()) e.set_call_notes(call_notes());
        throw;
    }
    out_.group(mark, st.loc);
}

namespace {

// What an instantiation's name calls, unless a user module of that name is
// in scope (ast::Stmt::dispatch caches it): a control statement, no
// built-in module, or kBuiltin + the built-in's place in the module table.
enum Dispatch : std::int16_t { kFor, kIntersectionFor, kLet, kEcho, kAssert, kChildren, kNoBuiltin, kBuiltin };

std::int16_t dispatch(const ast::Stmt& st) {
    if (st.dispatch >= 0) return st.dispatch;
    static constexpr std::string_view kControls[] = {"for", "intersection_for", "let", "echo", "assert", "children"};
    std::int16_t d = kNoBuiltin;
    for (std::size_t i = 0; i < std::size(kControls); ++i)
        if (st.name == kControls[i]) d = static_cast<std::int16_t>(i);
    if (d == kNoBuiltin)
        if (const int i = find_module_index(st.name); i >= 0) d = static_cast<std::int16_t>(kBuiltin + i);
    return st.dispatch = d;
}

}  // namespace

void Evaluator::stmt_for(const ast::Stmt& st, std::size_t k, Scope& loop, Scope& s) {
    const ast::Binding& b = st.args[k];
    if (b.name.empty() || !b.value) throw SourceError(b.loc, "for: expected name = range or list");
    Value seq = eval(*b.value, loop);
    std::uint64_t n = iteration_count(seq, b.loc);
    bool dollar = is_dollar(b.name);
    std::size_t slot = dollar ? dyn_.size() : loop.vars.size();
    if (dollar) dyn_.push_back(DynVar{b.name, Value()});
    else loop.add(VarSlot{b.name, Value(), &b.loc, true});
    const BlockInfo& body = prepare(st.body);
    for (std::uint64_t i = 0; i < n; ++i) {
        count_step(b.loc);
        Value item = seq.is_range() ? Value(seq.as_range().at(i)) : seq.as_list()[i];
        if (dollar) dyn_[slot].value = std::move(item);
        else loop.vars[slot].value = std::move(item);
        const std::size_t pass = out_.mark();
        if (k + 1 < st.args.size()) {
            stmt_for(st, k + 1, loop, s);
        } else if (!body.needs_scope) {
            for (const ast::Stmt* c : body.children) eval_stmt(*c, loop, false);
        } else {
            DynRestore restore(dyn_);
            Scope scope(&loop);
            bind_block(body, scope, false);
            for (const ast::Stmt* c : body.children) eval_stmt(*c, scope, false);
        }
        // intersection_for intersects its passes: each pass is one solid.
        if (k + 1 == st.args.size() && dispatch(st) == kIntersectionFor) out_.group(pass, st.loc);
    }
    if (dollar) dyn_.resize(slot);
    else loop.truncate(slot);
}

// ---------------------------------------------------------------- statements

void Evaluator::instantiate(const ast::Stmt& st, Scope& s, bool top_level) {
    const std::string& name = st.name;
    std::size_t mark = out_.mark();
    const std::int16_t d = dispatch(st);
    if (d == kFor || d == kIntersectionFor) {
        count_step(st.loc);
        for (std::size_t i = 0; i < st.args.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (st.args[i].name == st.args[j].name)
                    throw SourceError(st.args[i].loc, "'" + st.args[i].name + "' is already defined at " +
                                                          line_ref(st.args[i].loc, st.args[j].loc));
        DynRestore restore(dyn_);
        Scope loop(&s);
        loop.vars.reserve(st.args.size());
        if (!st.args.empty()) stmt_for(st, 0, loop, s);
        if (d == kFor) out_.group(mark, st.loc);
        else if (out_.produced_since(mark) > 1) out_.make_node(mark, graph::NodeKind::Intersection, st.loc);
        return;
    }
    if (d == kLet) {
        count_step(st.loc);
        DynRestore restore(dyn_);
        Scope ls(&s);
        bind_sequential(st.args, ls, "let");
        eval_block(st.body, ls, false);
        out_.group(mark, st.loc);
        return;
    }
    if (d == kEcho || d == kAssert) {
        count_step(st.loc);
        if (d == kEcho) do_echo(st.args, s, st.loc);
        else do_assert(st.args, s, st.loc);
        eval_block(st.body, s, false);
        out_.group(mark, st.loc);
        return;
    }
    if (d == kChildren) {
        count_step(st.loc);
        stmt_children(st, s);
        return;
    }
    for (Scope* sc = user_modules_ ? &s : nullptr; sc; sc = sc->parent) {
        auto find = [&](Scope* where) -> const ast::Stmt* {
            for (const ast::Stmt* m : where->modules)
                if (m->name == name) return m;
            return nullptr;
        };
        if (const ast::Stmt* def = find(sc)) {
            count_step(st.loc);
            call_module(*def, *sc, st, s);
            return;
        }
        for (Scope* u : sc->used)
            if (const ast::Stmt* def = find(u)) {
                count_step(st.loc);
                call_module(*def, *u, st, s);
                return;
            }
    }
    count_step(st.loc);
    if (d >= kBuiltin) return builtin_module(module_entry(d - kBuiltin), st, s, top_level);
    if (!lenient_) throw SourceError(st.loc, "unknown module '" + name + "'" + did_you_mean(name, s, NameKind::Module));
    warn(st.loc, "Ignoring unknown module '" + name + "'");
}

void Evaluator::eval_stmt(const ast::Stmt& st, Scope& s, bool top_level) {
    char probe;
    if (stack_floor && &probe < stack_floor)
        throw SourceError(st.loc, "evaluation nested too deeply (stack exhausted; lower the call depth limit)");
    if (st.kind != ast::StmtKind::Instantiate && st.kind != ast::StmtKind::If) {
        if (st.kind == ast::StmtKind::Block) {
            std::size_t mark = out_.mark();
            eval_block(st.body, s, false);
            out_.group(mark, st.loc);
        }
        return;  // definitions, include and use are handled by prepare()
    }
    // Debug modifiers, on a module call, for, let or if alike (OpenSCAD's
    // grammar allows no other statement after one).
    switch (st.modifier) {
        case ast::Modifier::Disable: return;  // `*`: not even evaluated, as in OpenSCAD
        case ast::Modifier::Background:  // `%`: evaluated (errors count), a ghost, not in the solid
        case ast::Modifier::Highlight: {  // `#`: in the solid, and a ghost too
            std::size_t mark = out_.mark();
            eval_plain(st, s, top_level);
            out_.group(mark, st.loc);
            const bool background = st.modifier == ast::Modifier::Background;
            if (out_.mark() > mark)
                record_ghost(st, background ? csg::GhostKind::Background : csg::GhostKind::Highlight, out_.pending.back());
            if (background) out_.pending.resize(mark);
            return;
        }
        case ast::Modifier::Root: {  // `!`: the first one becomes the whole solid
            std::size_t mark = out_.mark();
            const std::size_t ghosts = modules_.ghosts.size();
            eval_plain(st, s, top_level);
            out_.group(mark, st.loc);
            if (root_override_ < 0) {
                if (out_.mark() == mark) out_.make_node(mark, graph::NodeKind::Union, st.loc);
                root_override_ = out_.pending.back();
                root_ghosts_[0] = ghosts;
                root_ghosts_[1] = modules_.ghosts.size();
            }
            return;
        }
        default:
            if (st.kind == ast::StmtKind::Instantiate) return instantiate(st, s, top_level);  // eval_plain's first case
            eval_plain(st, s, top_level);
            return;
    }
}

// A module call or an if, its modifier already applied.
void Evaluator::eval_plain(const ast::Stmt& st, Scope& s, bool top_level) {
    if (st.kind == ast::StmtKind::Instantiate) {
        instantiate(st, s, top_level);
        return;
    }
    std::size_t mark = out_.mark();
    bool cond = eval(*st.value, s).truthy();
    eval_block(cond ? st.body : st.else_body, s, false);
    out_.group(mark, st.loc);
}

}  // namespace kerf::eval

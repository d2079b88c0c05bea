// Entry points: parse and evaluate on a thread with a large stack (so the
// call-depth limit, not the C stack, ends deep recursion), -D overrides,
// and the top-level union.
#include "interpreter/interpreter.hpp"

#include <pthread.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <utility>

#include "csg/usable_cpus.hpp"
#include "interpreter/evaluator.hpp"

namespace kerf {

namespace eval {

Evaluator::Evaluator(const EvalOptions& options)
    : opt_(options), lenient_(options.dialect == Dialect::Lenient),
      call_depth_(call_depth_limit(options.limits, options.dialect == Dialect::Lenient)), files_(options) {
    static const SourceLoc builtin_loc{};
    root_.add(VarSlot{"PI", Value(M_PI), &builtin_loc, true});
    root_.file = true;
    // Typical large scenes: a transform (and maybe an appearance) per leaf.
    std::size_t prims = static_cast<std::size_t>(std::min<std::uint64_t>(options.limits.primitives, 1u << 24));
    out_.max_nodes = 3 * prims + 1024;
    out_.max_matrices = prims + 1024;
    if (options.populate_ahead && options.threads != 1 && csg::usable_cpus() > 1) out_.populate_ahead.enable();
    if (lenient_) out_.warn_mixed = [this](const SourceLoc& loc, const std::string& message) { warn(loc, message); };
}

Evaluator::~Evaluator() = default;

void Evaluator::parse_defines() {
    for (const auto& define : opt_.defines) {
        // Not a structured binding: clang 14 (the fuzz build) cannot capture those.
        const std::string& name = define.first;
        const std::string& text = define.second;
        auto file = std::make_shared<SourceFile>();
        file->path = "-D " + name;
        file->text = name + " = " + text + ";";
        auto fail = [&](const std::string& msg) {
            throw DefineError("-D " + name + "=" + text + ": " + msg);
        };
        const ast::Expr* expr = nullptr;
        const ast::Program* parsed = nullptr;
        try {
            ParseOptions pl;
            pl.max_nesting = opt_.limits.nesting;
            pl.openscad = lenient_;
            parsed = &files_.keep(parse_program(file, pl));
        } catch (const SourceError& e) {
            fail(e.diagnostic().message);
        }
        const ast::Program& p = *parsed;
        if (p.stmts.size() == 1 && p.stmts[0]->kind == ast::StmtKind::Assign && p.stmts[0]->name == name)
            expr = p.stmts[0]->value.get();
        if (!expr) fail("expected NAME=EXPRESSION");
        Value v;
        try {
            v = eval(*expr, root_);
        } catch (const SourceError& e) {
            fail(e.diagnostic().message);
        }
        defines_.push_back(Define{name, std::move(v), false});
    }
}

graph::SceneGraph Evaluator::run(ast::Program program) {
    const ast::Program& prog = files_.keep(std::move(program));
    if (prog.file) main_path_ = prog.file->path;
    parse_defines();
    const BlockInfo& info = prepare(prog.stmts);
    for (const Define& d : defines_) {
        bool found = false;
        for (const ast::Stmt* a : info.assigns) found = found || a->name == d.name;
        // A `$` variable ($fn, $t...) may be set for the whole run even when
        // the script never assigns it, as with OpenSCAD's -D '$fn=64'.
        if (!found && !d.name.empty() && d.name[0] == '$') {
            note_viewport(d.name, d.value, nullptr);
            dyn_.push_back(DynVar{d.name, d.value});
            continue;
        }
        if (!found) throw DefineError("-D " + d.name + ": the script has no top-level binding '" + d.name + "'");
    }
    try {
        eval_block(prog.stmts, root_, true);
    } catch (const RunLimitError& e) {
        record_error(e);
    }
    out_.populate_ahead.stop();  // the arena is written: the rest faults its few pages itself
    SourceLoc top{prog.file, 1, 1};
    if (!out_.graph.camera) viewport_camera(top);
    if (exact_curves_)
        warn(first_exact_curve_, "$fn, $fa and $fs are ignored on " + std::to_string(exact_curves_) +
                                     (exact_curves_ == 1 ? " curved shape" : " curved shapes") +
                                     " (the first here): kerf renders curves exact" +
                                     (opt_.facets == FacetMode::Exact      ? " (--facets exact)"
                                      : opt_.facets == FacetMode::OpenScad ? " (--facets openscad does not cut these)"
                                                                           : ""));
    close_warnings();
    if (!errors_.empty() || (opt_.werror && !warnings_.empty())) throw_errors();
    if (root_override_ >= 0) {
        out_.pending.assign(1, static_cast<std::uint32_t>(root_override_));
    }
    out_.graph.root = out_.make_node(0, graph::NodeKind::Union, top);
    if (out_.graph.nodes[out_.graph.root].flat) {
        // A 2D model is shown as a plate 1 thick on z = 0, as OpenSCAD's
        // preview draws 2D shapes (docs/spec.md §10).
        out_.extrude(0, -0.5, 0.5, top);
        out_.graph.root = out_.make_node(0, graph::NodeKind::Union, top);
    }
    out_.pending.clear();
    build_ghost_roots(top);
    return std::move(out_.graph);
}

void Evaluator::record_error(const SourceError& e) {
    errors_.push_back(e.diagnostic());
    if (errors_.size() >= kMaxErrors) throw_errors();
}

void Evaluator::throw_errors() {
    close_warnings();
    std::vector<Diagnostic> all = warnings_;
    if (opt_.werror)
        for (Diagnostic& w : all) {
            w.severity = Severity::Error;
            w.message += " [--werror]";
        }
    all.insert(all.end(), errors_.begin(), errors_.end());
    // Under --werror the first warning is the first error of the run.
    SourceError first(opt_.werror && !warnings_.empty() ? all.front() : errors_.front());
    first.reported = std::move(all);
    throw first;
}

namespace {
bool same_place(const Diagnostic& a, const SourceLoc& loc, const std::string& message) {
    return a.loc.file == loc.file && a.loc.line == loc.line && a.loc.col == loc.col && a.message == message;
}
}  // namespace

// Innermost first, one note per call place: a place met again further out
// (a recursion, direct or mutual) adds to its note's count. Past
// kMaxCallNotes places, the innermost ones and the outermost (the user's
// first call) are kept and the last says how many calls were left out.
std::vector<Diagnostic> Evaluator::call_notes() const {
    std::vector<Diagnostic> notes;
    for (std::size_t i = calls_.size(); i > 0; --i) {
        const CallSite& c = calls_[i - 1];
        std::string message = "in '" + std::string(c.name) + "' called from here";
        bool seen = false;
        for (Diagnostic& n : notes)
            if (same_place(n, *c.at, message)) {
                ++n.repeats;
                seen = true;
                break;
            }
        if (!seen) notes.push_back(Diagnostic{Severity::Note, *c.at, std::move(message), 1, {}});
    }
    if (notes.size() > kMaxCallNotes) {
        std::uint64_t skipped = 0;
        for (std::size_t i = kMaxCallNotes - 1; i + 1 < notes.size(); ++i) skipped += notes[i].repeats;
        Diagnostic outermost = std::move(notes.back());
        outermost.message += " (" + std::to_string(skipped) + " calls between not shown)";
        notes.resize(kMaxCallNotes - 1);
        notes.push_back(std::move(outermost));
    }
    return notes;
}

void Evaluator::exact_curve(const Args& a, const SourceLoc& loc) {
    // The innermost binding of each name counts; OpenSCAD's defaults ask
    // for nothing kerf ignores.
    bool fn = false, fa = false, fs = false, set = a.facet_args;
    for (auto it = dyn_.rbegin(); it != dyn_.rend() && !set; ++it) {
        const double v = it->value.is_number() ? it->value.as_number() : 0;
        if (it->name == "$fn" && !std::exchange(fn, true)) set = v != 0;
        else if (it->name == "$fa" && !std::exchange(fa, true)) set = v != 12;
        else if (it->name == "$fs" && !std::exchange(fs, true)) set = v != 2;
    }
    if (!set) return;
    if (exact_curves_++ == 0) first_exact_curve_ = loc;
}

FacetVars Evaluator::facet_vars() const {
    FacetVars f;
    bool fn = false, fa = false, fs = false;
    for (auto it = dyn_.rbegin(); it != dyn_.rend(); ++it) {
        // A binding that is not a number leaves OpenSCAD's default, as there.
        const bool number = it->value.is_number();
        if (it->name == "$fn" && !std::exchange(fn, true) && number) f.fn = it->value.as_number();
        else if (it->name == "$fa" && !std::exchange(fa, true) && number) f.fa = it->value.as_number();
        else if (it->name == "$fs" && !std::exchange(fs, true) && number) f.fs = it->value.as_number();
    }
    return f;
}

// A warning met again in a loop costs a hash and a comparison of the call
// stack: 10^6 of them took ~15 s when each built its notes and compared
// them with every warning kept (quadratic in different warnings).
void Evaluator::warn(const SourceLoc& loc, std::string message) {
    const std::size_t key = std::hash<const void*>{}(loc.file.get()) ^ (std::size_t(loc.line) << 20) ^
                            std::size_t(loc.col) ^ (std::hash<std::string>{}(message) << 1);
    // find(), not [], and notes built only for a kept warning's place: past
    // the cap a warning not kept costs a count, no memory.
    const auto found = warning_index_.find(key);
    static const std::vector<std::size_t> none;
    const std::vector<std::size_t>& same_key = found == warning_index_.end() ? none : found->second;
    auto raw_calls_equal = [&](const std::vector<CallSite>& c) {
        if (c.size() != calls_.size()) return false;
        for (std::size_t i = 0; i < c.size(); ++i)
            if (c[i].at != calls_[i].at || c[i].name != calls_[i].name) return false;
        return true;
    };
    bool same_place_kept = false;
    for (std::size_t i : same_key) {
        if (!same_place(warnings_[i], loc, message)) continue;
        if (raw_calls_equal(warning_calls_[i])) {
            ++warnings_[i].repeats;
            return;
        }
        same_place_kept = true;
    }
    // The same warning reached through other calls is another diagnostic,
    // unless its notes are the same (a recursion one level deeper).
    std::vector<Diagnostic> notes;
    if (same_place_kept || warnings_.size() < kMaxWarnings || warnings_dropped_ == 0) notes = call_notes();
    auto same_calls = [&](const Diagnostic& w) {
        if (w.notes.size() != notes.size()) return false;
        for (std::size_t i = 0; i < notes.size(); ++i)
            if (!same_place(w.notes[i], notes[i].loc, notes[i].message)) return false;
        return true;
    };
    if (same_place_kept)
        for (std::size_t i : same_key)
            if (same_place(warnings_[i], loc, message) && same_calls(warnings_[i])) {
                ++warnings_[i].repeats;
                warning_calls_[i] = calls_;
                return;
            }
    if (warnings_.size() >= kMaxWarnings) {
        if (warnings_dropped_++ == 0) {
            first_dropped_ = message;
            warnings_.push_back(Diagnostic{Severity::Warning, loc, {}, 1, std::move(notes)});
            warning_calls_.push_back({});
        }
        return;
    }
    warning_index_[key].push_back(warnings_.size());
    warnings_.push_back(Diagnostic{Severity::Warning, loc, std::move(message), 1, std::move(notes)});
    warning_calls_.push_back(calls_);
}

// The last warning, when some were not kept, says which first and how many
// more times a warning was not kept (each occurrence: past the cap kerf
// cannot tell a repeat from another warning without keeping it).
void Evaluator::close_warnings() {
    if (warnings_dropped_ == 0) return;
    warnings_[kMaxWarnings].message =
        warnings_dropped_ == 1 ? first_dropped_
                               : first_dropped_ + " (and " + std::to_string(warnings_dropped_ - 1) +
                                     " more occurrences of warnings not shown: kerf shows " + std::to_string(kMaxWarnings + 1) +
                                     " different ones at most)";
}

}  // namespace eval

namespace {

// Runs fn on a thread with a 512 MB stack (address space only; pages are
// committed as they are touched) and rethrows what it threw.
constexpr std::size_t big_stack = std::size_t(512) << 20;

void run_with_big_stack(const std::function<void()>& fn) {
    struct Task {
        const std::function<void()>* fn;
        std::exception_ptr error;
        std::size_t stack;
    } task{&fn, nullptr, big_stack};
    auto body = [](void* p) -> void* {
        auto* t = static_cast<Task*>(p);
        char top;
        // Keep 1/8 of the stack (at least 1 MB) for what runs below the
        // last check: builtins, formatting, exception unwinding.
        std::size_t margin = std::max<std::size_t>(t->stack / 8, std::size_t(1) << 20);
        auto top_addr = reinterpret_cast<std::uintptr_t>(&top);
        eval::stack_floor = reinterpret_cast<const char*>(top_addr - (t->stack - margin));
        try {
            (*t->fn)();
        } catch (...) {
            t->error = std::current_exception();
        }
        eval::stack_floor = nullptr;
        return nullptr;
    };
    pthread_attr_t attr;
    pthread_t thread;
    bool started = pthread_attr_init(&attr) == 0 &&
                   pthread_attr_setstacksize(&attr, big_stack) == 0 &&
                   pthread_create(&thread, &attr, body, &task) == 0;
    pthread_attr_destroy(&attr);
    if (started) pthread_join(thread, nullptr);
    if (!started) {  // no thread available: use the current (default 8 MB) stack
        task.stack = std::size_t(8) << 20;
        body(&task);
    }
    if (task.error) std::rethrow_exception(task.error);
}

}  // namespace

bool is_lenient(Dialect dialect, std::string_view main_path) {
    if (dialect != Dialect::Auto) return dialect == Dialect::Lenient;
    return main_path.size() > 5 && main_path.substr(main_path.size() - 5) == ".scad";
}

EvalResult evaluate_source(std::shared_ptr<const SourceFile> file, const EvalOptions& given) {
    // The dialect is decided once, by the main file, for every file of the run.
    EvalOptions options = given;
    options.dialect = is_lenient(given.dialect, file->path) ? Dialect::Lenient : Dialect::Strict;
    EvalResult result;
    run_with_big_stack([&] {
        ParseOptions pl;
        pl.max_nesting = options.limits.nesting;
        pl.openscad = options.dialect == Dialect::Lenient;
        ast::Program program = parse_program(file, pl);
        eval::Evaluator ev(options);
        result.graph = ev.run(std::move(program));
        result.warnings = ev.take_warnings();
    });
    return result;
}

EvalResult evaluate_file(const std::string& path, const EvalOptions& options) {
    if (options.on_dependency) options.on_dependency(path);
    return evaluate_source(read_source_file(path), options);
}

}  // namespace kerf

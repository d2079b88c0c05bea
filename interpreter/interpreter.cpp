// Entry points: parse and evaluate on a thread with a large stack (so the
// call-depth limit, not the C stack, ends deep recursion), -D overrides,
// and the top-level union.
#include "interpreter/interpreter.hpp"

#include <pthread.h>

#include <cmath>
#include <exception>
#include <functional>

#include "interpreter/evaluator.hpp"

namespace kerf {

namespace eval {

Evaluator::Evaluator(const EvalOptions& options) : opt_(options) {
    static const SourceLoc builtin_loc{};
    root_.vars.push_back(VarSlot{"PI", Value(M_PI), &builtin_loc, true});
}

Evaluator::~Evaluator() = default;

void Evaluator::parse_defines() {
    for (const auto& [name, text] : opt_.defines) {
        auto file = std::make_shared<SourceFile>();
        file->path = "-D " + name;
        file->text = name + " = " + text + ";";
        auto fail = [&](const std::string& msg) {
            throw SourceError(SourceLoc{}, "-D " + name + "=" + text + ": " + msg);
        };
        const ast::Expr* expr = nullptr;
        try {
            ParseLimits pl;
            pl.max_nesting = opt_.limits.nesting;
            define_programs_.push_back(parse_program(file, pl));
        } catch (const SourceError& e) {
            fail(e.diagnostic().message);
        }
        const ast::Program& p = define_programs_.back();
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

scene::SceneGraph Evaluator::run(ast::Program program) {
    programs_.push_back(std::move(program));
    const ast::Program& prog = programs_.back();
    parse_defines();
    const BlockInfo& info = prepare(prog.stmts);
    for (const Define& d : defines_) {
        bool found = false;
        for (const ast::Stmt* a : info.assigns) found = found || a->name == d.name;
        if (!found) throw SourceError(SourceLoc{}, "-D " + d.name + ": the script has no top-level binding '" + d.name + "'");
    }
    eval_block(prog.stmts, root_, true);
    SourceLoc top{prog.file, 1, 1};
    if (root_override_ >= 0) {
        out_.pending.assign(1, static_cast<std::uint32_t>(root_override_));
    }
    out_.graph.root = out_.make_node(0, scene::NodeKind::Union, top);
    out_.pending.clear();
    return std::move(out_.graph);
}

}  // namespace eval

namespace {

// Runs fn on a thread with a 512 MB stack (address space only; pages are
// committed as they are touched) and rethrows what it threw.
void run_with_big_stack(const std::function<void()>& fn) {
    struct Task {
        const std::function<void()>* fn;
        std::exception_ptr error;
    } task{&fn, nullptr};
    auto body = [](void* p) -> void* {
        auto* t = static_cast<Task*>(p);
        try {
            (*t->fn)();
        } catch (...) {
            t->error = std::current_exception();
        }
        return nullptr;
    };
    pthread_attr_t attr;
    pthread_t thread;
    bool started = pthread_attr_init(&attr) == 0 &&
                   pthread_attr_setstacksize(&attr, std::size_t(512) << 20) == 0 &&
                   pthread_create(&thread, &attr, body, &task) == 0;
    pthread_attr_destroy(&attr);
    if (started) pthread_join(thread, nullptr);
    else body(&task);  // no thread available: use the current stack
    if (task.error) std::rethrow_exception(task.error);
}

}  // namespace

EvalResult evaluate_source(std::shared_ptr<const SourceFile> file, const EvalOptions& options) {
    EvalResult result;
    run_with_big_stack([&] {
        ParseLimits pl;
        pl.max_nesting = options.limits.nesting;
        ast::Program program = parse_program(file, pl);
        eval::Evaluator ev(options);
        result.graph = ev.run(std::move(program));
    });
    return result;
}

EvalResult evaluate_file(const std::string& path, const EvalOptions& options) {
    return evaluate_source(read_source_file(path), options);
}

}  // namespace kerf

#include "grammar/builder.hpp"

#include <algorithm>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "grammar/literals.hpp"

namespace kerf::grammar {

using ast::Expr;
using ast::ExprKind;
using ast::ExprPtr;
using ast::Stmt;
using ast::StmtKind;
using ast::StmtPtr;

namespace {
// The builder's stacks are balanced by construction of the grammar; a
// violation is a bug in kerf, not in the script.
[[noreturn]] void internal_error(const char* what) {
    throw std::logic_error(std::string("kerf parser: unbalanced AST construction: ") + what);
}

std::uint32_t clamp32(std::size_t v) {
    return static_cast<std::uint32_t>(std::min<std::size_t>(v, std::numeric_limits<std::uint32_t>::max()));
}
}  // namespace

Builder::Builder(std::shared_ptr<const SourceFile> file, std::size_t max_nesting) : file_(std::move(file)) {
    nesting.max = max_nesting;
    auto root = std::make_unique<Stmt>();
    root->kind = StmtKind::Block;
    open_.push_back(std::move(root));
}

SourceLoc Builder::loc(std::size_t line, std::size_t col) const { return SourceLoc{file_, clamp32(line), clamp32(col)}; }

// ---- expression stack ---------------------------------------------------------

ExprPtr Builder::make(ExprKind kind, SourceLoc at) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->loc = std::move(at);
    return e;
}

// Operator chains (`1+1+1+...`, `a[0][0]...`) build trees deeper than the
// source nests; the interpreter and even the tree's destructor recurse over
// them, so the tree height is bounded too — but by a larger multiple of the
// nesting limit, because a long flat sum is not "nesting" to the person who
// wrote it (generated scripts contain them). The C stack stays bounded.
void Builder::push(ExprPtr e, std::uint32_t height) {
    const std::size_t max_height = kChainFactor * nesting.max;
    if (height > max_height)
        throw SourceError(e->loc, "expression deeper than " + std::to_string(max_height) +
                                      " (a chain of operators this long must be split)");
    exprs_.push_back(Slot{std::move(e), height});
}

ExprPtr Builder::pop(std::uint32_t& height) {
    if (exprs_.empty()) internal_error("expression");
    Slot s = std::move(exprs_.back());
    exprs_.pop_back();
    height = std::max(height, s.height);
    return std::move(s.expr);
}

ExprPtr Builder::pop() {
    std::uint32_t ignored = 0;
    return pop(ignored);
}

std::vector<ExprPtr> Builder::pop_items(std::uint32_t& height) {
    if (marks_.empty() || marks_.back() > exprs_.size()) internal_error("item mark");
    const std::size_t first = marks_.back();
    marks_.pop_back();
    std::vector<ExprPtr> items;
    items.reserve(exprs_.size() - first);
    for (std::size_t i = first; i < exprs_.size(); ++i) {
        height = std::max(height, exprs_[i].height);
        items.push_back(std::move(exprs_[i].expr));
    }
    exprs_.resize(first);
    return items;
}

void Builder::number(std::string_view text, SourceLoc at) {
    const auto value = parse_number(text);
    if (!value) throw SourceError(std::move(at), "malformed number '" + std::string(text.substr(0, 40)) + "'");
    auto e = make(ExprKind::Number, std::move(at));
    e->number = *value;
    push(std::move(e), 1);
}

void Builder::string(std::string_view literal, SourceLoc at) {
    auto e = make(ExprKind::String, std::move(at));
    e->text = decode_string(literal);
    push(std::move(e), 1);
}

void Builder::boolean(bool value, SourceLoc at) {
    auto e = make(ExprKind::Bool, std::move(at));
    e->number = value ? 1 : 0;
    push(std::move(e), 1);
}

void Builder::undef(SourceLoc at) { push(make(ExprKind::Undef, std::move(at)), 1); }

void Builder::ident(std::string_view name, SourceLoc at) {
    auto e = make(ExprKind::Ident, std::move(at));
    e->text = name;
    push(std::move(e), 1);
}

void Builder::op(std::string_view text) { ops_.emplace_back(text); }

void Builder::unary(SourceLoc at) {
    if (ops_.empty()) internal_error("operator");
    std::uint32_t h = 0;
    auto e = make(ExprKind::Unary, std::move(at));
    e->items.reserve(1);
    e->text = std::move(ops_.back());
    ops_.pop_back();
    e->items.push_back(pop(h));
    push(std::move(e), h + 1);
}

void Builder::binary(SourceLoc at) {
    if (ops_.empty()) internal_error("operator");
    std::uint32_t h = 0;
    auto e = make(ExprKind::Binary, std::move(at));
    e->items.reserve(2);
    e->text = std::move(ops_.back());
    ops_.pop_back();
    auto rhs = pop(h);
    auto lhs = pop(h);
    e->items.push_back(std::move(lhs));
    e->items.push_back(std::move(rhs));
    push(std::move(e), h + 1);
}

void Builder::ternary(SourceLoc at) {
    std::uint32_t h = 0;
    auto e = make(ExprKind::Ternary, std::move(at));
    e->items.reserve(3);
    auto otherwise = pop(h);
    auto then = pop(h);
    auto cond = pop(h);
    e->items.push_back(std::move(cond));
    e->items.push_back(std::move(then));
    e->items.push_back(std::move(otherwise));
    push(std::move(e), h + 1);
}

void Builder::index(SourceLoc at) {
    std::uint32_t h = 0;
    auto e = make(ExprKind::Index, std::move(at));
    e->items.reserve(2);
    auto i = pop(h);
    auto object = pop(h);
    e->items.push_back(std::move(object));
    e->items.push_back(std::move(i));
    push(std::move(e), h + 1);
}

void Builder::member_name(std::string_view name) { member_ = name; }

void Builder::member(SourceLoc at) {
    std::uint32_t h = 0;
    auto e = make(ExprKind::Member, std::move(at));
    e->items.reserve(1);
    e->text = member_;
    e->items.push_back(pop(h));
    push(std::move(e), h + 1);
}

void Builder::mark_items() { marks_.push_back(exprs_.size()); }

void Builder::list_kind(ExprKind kind) { list_kind_ = kind; }

void Builder::list(SourceLoc at) {
    std::uint32_t h = 0;
    auto e = make(list_kind_, std::move(at));
    e->items = pop_items(h);
    if (list_kind_ == ExprKind::Range && e->items.size() != 2 && e->items.size() != 3) internal_error("range");
    list_kind_ = ExprKind::List;
    push(std::move(e), h + 1);
}

void Builder::list_if(SourceLoc at) {
    std::uint32_t h = 0;
    auto e = make(ExprKind::ListIf, std::move(at));
    e->items = pop_items(h);
    if (e->items.size() != 2 && e->items.size() != 3) internal_error("list if");
    push(std::move(e), h + 1);
}

void Builder::c_style_for() { c_style_pending_ = true; }

// Set here, after the header, and read by list_for: a `for` inside the
// condition or the element has completed its own header by then.
void Builder::for_header() {
    for_kinds_.push_back(c_style_pending_);
    c_style_pending_ = false;
}

void Builder::list_for(SourceLoc at) {
    if (for_kinds_.empty()) internal_error("for header");
    const bool c_style = for_kinds_.back();
    for_kinds_.pop_back();
    if (!c_style) {
        generator(ExprKind::ListFor, std::move(at));
        return;
    }
    // Stacks: exprs [.., cond, element], bindings [.., init, incr].
    std::uint32_t h = 0, hc = 0;
    auto e = make(ExprKind::ListForC, std::move(at));
    auto element = pop(h);
    auto cond = pop(hc);
    BindingList incr = pop_bindings();
    BindingList init = pop_bindings();
    e->bindings = std::move(init.items);
    e->args = std::move(incr.items);
    e->items.reserve(2);
    e->items.push_back(std::move(cond));
    e->items.push_back(std::move(element));
    push(std::move(e), std::max({h, hc, init.height, incr.height}) + 1);
}

void Builder::generator(ExprKind kind, SourceLoc at) {
    std::uint32_t h = 0;
    auto e = make(kind, std::move(at));
    auto element = pop(h);
    BindingList b = pop_bindings();
    e->bindings = std::move(b.items);
    e->items.reserve(1);
    e->items.push_back(std::move(element));
    push(std::move(e), std::max(h, b.height) + 1);
}

void Builder::list_let(SourceLoc at) { generator(ExprKind::ListLet, std::move(at)); }

void Builder::list_each(SourceLoc at) {
    std::uint32_t h = 0;
    auto e = make(ExprKind::ListEach, std::move(at));
    e->items.push_back(pop(h));
    push(std::move(e), h + 1);
}

void Builder::let(SourceLoc at) { generator(ExprKind::Let, std::move(at)); }

void Builder::function_literal(SourceLoc at) { generator(ExprKind::Function, std::move(at)); }

void Builder::apply(SourceLoc at) {
    BindingList b = pop_bindings();
    std::uint32_t h = 0;
    auto callee = pop(h);
    auto e = make(ExprKind::Apply, std::move(at));
    e->items.push_back(std::move(callee));
    e->args = std::move(b.items);
    push(std::move(e), std::max(h, b.height) + 1);
}

void Builder::echo(SourceLoc at) {
    std::uint32_t h = 0;
    auto e = make(ExprKind::Echo, std::move(at));
    auto body = pop(h);
    BindingList b = pop_bindings();
    e->args = std::move(b.items);
    e->items.reserve(1);
    e->items.push_back(std::move(body));
    push(std::move(e), std::max(h, b.height) + 1);
}

void Builder::assert_(SourceLoc at) {
    echo(std::move(at));
    exprs_.back().expr->kind = ExprKind::Assert;
}

void Builder::push_name(std::string_view name, SourceLoc at) { names_.push_back(Name{std::string(name), std::move(at)}); }

Builder::Name Builder::pop_name() {
    if (names_.empty()) internal_error("name");
    Name n = std::move(names_.back());
    names_.pop_back();
    return n;
}

void Builder::call() {
    Name n = pop_name();
    BindingList b = pop_bindings();
    auto e = make(ExprKind::Call, std::move(n.loc));
    e->text = std::move(n.text);
    e->args = std::move(b.items);
    push(std::move(e), b.height + 1);
}

// ---- binding lists ----------------------------------------------------------------

// Binding lists are collected in scratch vectors that keep their capacity
// (one per open list level) and copied out at their exact size: one
// allocation per non-empty list instead of one per growth step.
void Builder::open_bindings() {
    if (open_bindings_ == bindings_.size()) bindings_.emplace_back();
    ++open_bindings_;
}

Builder::BindingList Builder::pop_bindings() {
    if (open_bindings_ == 0) internal_error("binding list");
    BindingList& scratch = bindings_[--open_bindings_];
    BindingList out;
    out.height = scratch.height;
    out.items.reserve(scratch.items.size());
    std::move(scratch.items.begin(), scratch.items.end(), std::back_inserter(out.items));
    scratch.items.clear();
    scratch.height = 0;
    return out;
}

void Builder::binding_name(std::string_view name, SourceLoc at) {
    if (open_bindings_ == 0) internal_error("binding list");
    bindings_[open_bindings_ - 1].items.push_back(ast::Binding{std::string(name), nullptr, std::move(at)});
}

void Builder::binding_value() {
    if (open_bindings_ == 0 || bindings_[open_bindings_ - 1].items.empty()) internal_error("binding");
    std::uint32_t h = 0;
    auto value = pop(h);
    auto& list = bindings_[open_bindings_ - 1];
    list.items.back().value = std::move(value);
    list.height = std::max(list.height, h);
}

void Builder::positional(SourceLoc at) {
    if (open_bindings_ == 0) internal_error("binding list");
    std::uint32_t h = 0;
    auto value = pop(h);
    auto& list = bindings_[open_bindings_ - 1];
    list.items.push_back(ast::Binding{std::string(), std::move(value), std::move(at)});
    list.height = std::max(list.height, h);
}

// ---- statements ---------------------------------------------------------------------

// Several stacked modifiers (`#!cube();`): `*` anywhere wins (the statement
// is disabled whatever else is asked), otherwise the leftmost is kept.
void Builder::modifier(char c) {
    ast::Modifier m = ast::Modifier::None;
    switch (c) {
        case '*': m = ast::Modifier::Disable; break;
        case '!': m = ast::Modifier::Root; break;
        case '#': m = ast::Modifier::Highlight; break;
        case '%': m = ast::Modifier::Background; break;
        default: internal_error("modifier");
    }
    if (modifier_ == ast::Modifier::None || m == ast::Modifier::Disable) modifier_ = m;
}

void Builder::append(StmtPtr s) {
    if (open_.empty()) internal_error("statement");
    Stmt& parent = *open_.back();
    (parent.has_else ? parent.else_body : parent.body).push_back(std::move(s));
}

void Builder::empty(SourceLoc at) {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::Empty;
    s->loc = std::move(at);
    append(std::move(s));
}

void Builder::open(StmtKind kind, std::string_view name, SourceLoc at) {
    auto s = std::make_unique<Stmt>();
    s->kind = kind;
    s->name = name;
    s->loc = std::move(at);
    s->modifier = modifier_;
    modifier_ = ast::Modifier::None;
    open_.push_back(std::move(s));
}

void Builder::set_name(std::string_view name) { open_.back()->name = name; }

void Builder::set_args() { open_.back()->args = pop_bindings().items; }

void Builder::set_params() { open_.back()->params = pop_bindings().items; }

void Builder::set_value() { open_.back()->value = pop(); }

void Builder::start_else() { open_.back()->has_else = true; }

void Builder::close() {
    if (open_.size() < 2) internal_error("close");
    StmtPtr s = std::move(open_.back());
    open_.pop_back();
    append(std::move(s));
}

void Builder::assign(SourceLoc at) {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::Assign;
    s->loc = std::move(at);
    s->value = pop();
    s->name = pop_name().text;
    append(std::move(s));
}

void Builder::function_def(SourceLoc at) {
    auto s = std::make_unique<Stmt>();
    s->kind = StmtKind::FunctionDef;
    s->loc = std::move(at);
    s->value = pop();
    s->params = pop_bindings().items;
    s->name = pop_name().text;
    append(std::move(s));
}

void Builder::path(std::string text) { path_ = std::move(text); }

void Builder::include(StmtKind kind, SourceLoc at) {
    auto s = std::make_unique<Stmt>();
    s->kind = kind;
    s->loc = std::move(at);
    s->name = std::move(path_);
    path_.clear();
    append(std::move(s));
}

ast::Program Builder::finish() {
    if (open_.size() != 1 || !exprs_.empty() || !marks_.empty() || open_bindings_ != 0 || !names_.empty() ||
        !ops_.empty())
        internal_error("leftovers at end of input");
    ast::Program p;
    p.file = file_;
    p.stmts = std::move(open_.front()->body);
    open_.clear();
    return p;
}

}  // namespace kerf::grammar

#include "interpreter/suggest.hpp"

#include <algorithm>
#include <vector>

#include "interpreter/evaluator.hpp"
#include "interpreter/modules/module_call.hpp"

namespace kerf::eval {
namespace {

// Levenshtein distance, one row at a time.
std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

}  // namespace

void Suggestion::offer(std::string_view name) {
    if (name == wanted_ || name.empty() || wanted_.size() < 3) return;  // one or two letters: any name is "close"
    const std::size_t limit = std::max<std::size_t>(1, (wanted_.size() + 2) / 3);
    const std::size_t longer = std::max(name.size(), wanted_.size());
    if (longer - std::min(name.size(), wanted_.size()) > limit) return;
    const std::size_t d = edit_distance(wanted_, name);
    if (d <= limit && d < distance_) {
        distance_ = d;
        best_ = name;
    }
}

std::string Suggestion::text() const { return best_.empty() ? std::string() : "; did you mean '" + best_ + "'?"; }

std::string Evaluator::did_you_mean(std::string_view name, Scope& s, NameKind kind) {
    Suggestion best(name);
    auto offer_scope = [&](Scope* sc) {
        if (kind == NameKind::Variable)
            for (const VarSlot& v : sc->vars) best.offer(v.name);
        for (const ast::Stmt* d : kind == NameKind::Function ? sc->functions : sc->modules)
            if (kind != NameKind::Variable) best.offer(d->name);
    };
    for (Scope* sc = &s; sc; sc = sc->parent) {
        offer_scope(sc);
        for (Scope* u : sc->used) offer_scope(u);
    }
    if (kind == NameKind::Variable)
        for (const DynVar& d : dyn_) best.offer(d.name);
    if (kind == NameKind::Function)
        for (std::string_view n : builtin_names()) best.offer(n);
    if (kind == NameKind::Module)
        for (std::string_view n : module_names()) best.offer(n);
    return best.text();
}

}  // namespace kerf::eval

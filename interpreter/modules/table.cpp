// Dispatch of the builtin modules (docs/spec.md §4–§6) and their argument matching.
#include <string_view>

#include "interpreter/evaluator.hpp"

namespace kerf::eval {

Args Evaluator::match_args(const char* callee, std::initializer_list<const char*> names, const ast::Stmt& st,
                           Scope& s) {
    Args a{callee, &st, std::vector<Value>(names.size()), std::vector<bool>(names.size(), false)};
    std::size_t positional = 0;
    for (const ast::Binding& b : st.args) {
        std::size_t i = names.size();
        if (b.name.empty()) {
            if (positional >= names.size())
                throw SourceError(b.loc, std::string("too many arguments for '") + callee + "' (takes " +
                                             std::to_string(names.size()) + ")");
            i = positional++;
        } else {
            if (b.name[0] == '$') continue;  // $fn, $fa, $fs...: accepted and ignored
            std::size_t j = 0;
            for (const char* n : names) {
                if (b.name == n) i = j;
                ++j;
            }
            if (i == names.size())
                throw SourceError(b.loc, "unknown argument '" + b.name + "' for '" + callee + "'");
        }
        if (a.given[i])
            throw SourceError(b.loc, std::string("argument '") + names.begin()[i] + "' given twice to '" + callee + "'");
        a.given[i] = true;
        a.values[i] = b.value ? eval(*b.value, s) : Value();
    }
    return a;
}

bool Evaluator::builtin_module(const ast::Stmt& st, Scope& s, bool top_level) {
    std::string_view n = st.name;
    if (n == "sphere" || n == "cube" || n == "cylinder" || n == "cone" || n == "torus" || n == "plane" ||
        n == "paraboloid" || n == "hyperboloid" || n == "polyhedron" || n == "import") {
        solid(n, st, s);
        return true;
    }
    if (n == "union" || n == "intersection" || n == "difference" || n == "translate" || n == "rotate" ||
        n == "scale" || n == "mirror" || n == "multmatrix" || n == "render" || n == "group") {
        transform(n, st, s);
        return true;
    }
    if (n == "color" || n == "material") {
        appearance(n, st, s);
        return true;
    }
    if (n == "camera" || n == "light" || n == "background") {
        scene_statement(n, st, s, top_level);
        return true;
    }
    return false;
}

}  // namespace kerf::eval

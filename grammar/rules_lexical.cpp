#include "grammar/rules_lexical.hpp"

namespace kerf::grammar {

bool is_keyword(std::string_view w) noexcept {
    switch (w.size()) {
        case 2: return w == "if";
        case 3: return w == "for" || w == "let" || w == "use";
        case 4: return w == "else" || w == "true";
        case 5: return w == "false" || w == "undef";
        case 6: return w == "module";
        case 7: return w == "include";
        case 8: return w == "function";
        default: return false;
    }
}

}  // namespace kerf::grammar

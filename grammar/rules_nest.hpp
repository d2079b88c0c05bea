// The nesting guard of the grammar (docs/spec.md §8: "nesting depth of source 256").
//
// Every recursive path through the grammar passes through a `nest<>` rule,
// so the C stack used by the parser is bounded by max_nesting times the
// (constant) depth of rule frames per level, whatever the input: `((((`,
// `[[[[`, `{{{{`, `-----x`, `2^2^2^...`, `a?b:a?b:...`, `if..else if..`, and
// chains of child statements all end in a located error, not a crash.
#pragma once
#include <cstddef>
#include <string>

#include <tao/pegtl.hpp>

namespace kerf::grammar {

namespace pg = tao::pegtl;

struct NestingCounter {
    std::size_t depth = 0;
    std::size_t max = 256;
};

// Matches Head, then counts one nesting level while it matches Rules...
// (plain seq semantics: put must<> around Rules where a failure is an error).
// Counting starts only once Head has matched, so a `nest<>` that is merely
// tried as an alternative never raises the nesting error; the error is
// located at Head's first byte. The parser state must have a member
// `NestingCounter nesting`.
template <typename Head, typename... Rules>
struct nest : pg::seq<Head, Rules...> {
    template <pg::apply_mode A, pg::rewind_mode M, template <typename...> class Action,
              template <typename...> class Control, typename Input, typename State>
    static bool match(Input& in, State& st) {
        auto m = in.template mark<M>();
        using m_t = decltype(m);
        const auto start = in.iterator();
        if (!Control<Head>::template match<A, m_t::next_rewind_mode, Action, Control>(in, st)) return m(false);
        NestingCounter& n = st.nesting;
        if (n.depth >= n.max)
            throw pg::parse_error("nesting deeper than " + std::to_string(n.max), in.position(start));
        ++n.depth;
        struct Leave {
            NestingCounter& n;
            ~Leave() { --n.depth; }
        } leave{n};
        return m(Control<pg::seq<Rules...>>::template match<A, m_t::next_rewind_mode, Action, Control>(in, st));
    }
};

// Counts one level around Rule itself (for rules only tried where they are
// required, like the child statement of an instantiation).
template <typename Rule>
struct counted : nest<pg::success, Rule> {};

}  // namespace kerf::grammar

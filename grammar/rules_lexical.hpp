// Lexical PEGTL rules of .sdl (docs/spec.md §1): whitespace and comments, names,
// keywords, numbers, strings and punctuation.
//
// Convention: every token rule ending in `_tok` (and every punctuation rule)
// swallows the whitespace and comments AFTER it, so each rule starts exactly
// at its first significant byte. Actions therefore read a node's location
// from the start of the matched input, and a `must<>` failure is reported at
// the offending byte rather than at the preceding blank space.
#pragma once
#include <cctype>
#include <string_view>

#include <tao/pegtl.hpp>
#include <tao/pegtl/contrib/analyze_traits.hpp>

namespace kerf::grammar {

namespace pg = tao::pegtl;

// `/* ... */`, not nested. Hand-written so an unterminated comment is
// reported at its opening `/*` (a `must<>` would point at the end of file)
// and so the search for `*/` is one linear scan.
struct block_comment {
    using rule_t = block_comment;
    using subs_t = pg::empty_list;

    template <pg::apply_mode, pg::rewind_mode, template <typename...> class,
              template <typename...> class, typename Input, typename... States>
    static bool match(Input& in, States&&...) {
        if (in.size(2) < 2 || in.peek_char(0) != '/' || in.peek_char(1) != '*') return false;
        std::string_view rest(in.current() + 2, static_cast<std::size_t>(in.end() - in.current()) - 2);
        const auto close = rest.find("*/");
        if (close == std::string_view::npos) throw pg::parse_error("unterminated comment", in);
        in.bump(close + 4);
        return true;
    }
};

// True when the parser state (the Builder) asks for OpenSCAD's lexical
// leniency (ParseOptions::openscad).
template <typename... States>
bool openscad_mode(const States&... states) {
    auto one = [](const auto& s) {
        if constexpr (requires { s.openscad; }) return bool(s.openscad);
        else return false;
    };
    return (false || ... || one(states));
}

// Matches nothing, and only in the OpenSCAD dialect: guards its extra
// alternatives (an empty list element or argument).
// `"..."` with the escapes `\" \\ \n \t \r`. Decision (docs/spec.md §1 lists only
// the first four; `\r` is accepted too because OpenSCAD has it): any other
// escape (`\x41`, `\u263A`, `\q`, ...) is an error at its backslash, in line
// with the spec's "strict" rule, instead of OpenSCAD's warn-and-keep.
// Strings may span lines, as in OpenSCAD. Unterminated strings are reported
// at the opening quote. The text is decoded by the action (decode_string).
struct string_lit {
    using rule_t = string_lit;
    using subs_t = pg::empty_list;

    // OpenSCAD's `\x41` (0x01-0x7F), `\u263A` and `\U01F600`: the length of
    // the escape at p (0: not one), in both dialects.
    static std::size_t openscad_escape(const char* p, const char* end) noexcept {
        auto hex = [&](const char* q, std::size_t n) {
            for (std::size_t i = 0; i < n; ++i)
                if (q + i >= end || !std::isxdigit(static_cast<unsigned char>(q[i]))) return false;
            return true;
        };
        if (p[1] == 'x' && p + 2 < end && p[2] >= '0' && p[2] <= '7' && hex(p + 3, 1)) return 4;
        if (p[1] == 'u' && hex(p + 2, 4)) return 6;
        if (p[1] == 'U' && hex(p + 2, 6)) return 8;
        return 0;
    }

    template <pg::apply_mode, pg::rewind_mode, template <typename...> class,
              template <typename...> class, typename Input, typename... States>
    static bool match(Input& in, States&&... st) {
        if (in.empty() || in.peek_char() != '"') return false;
        const char* p = in.current() + 1;
        const char* end = in.end();
        while (p < end && *p != '"') {
            if (*p == '\\') {
                if (p + 1 == end) throw pg::parse_error("unterminated string", in);
                const char e = p[1];
                if (const std::size_t n = openscad_escape(p, end)) {  // both dialects
                    p += n;
                    continue;
                }
                if (openscad_mode(st...)) {  // any other escape: the character, as OpenSCAD's lexer
                    p += 2;
                    continue;
                }
                if (e != '"' && e != '\\' && e != 'n' && e != 't' && e != 'r') {
                    in.bump(static_cast<std::size_t>(p - in.current()));
                    throw pg::parse_error("invalid escape sequence in string", in);
                }
                p += 2;
            } else {
                ++p;
            }
        }
        if (p >= end) throw pg::parse_error("unterminated string", in);
        in.bump(static_cast<std::size_t>(p + 1 - in.current()));
        return true;
    }
};

struct line_comment : pg::seq<pg::two<'/'>, pg::until<pg::eolf>> {};

// ---- names and keywords -------------------------------------------------
// True for module function if else for let include use true false undef.
bool is_keyword(std::string_view word) noexcept;

// `[A-Za-z_][A-Za-z0-9_]*` that is not a keyword, or `$` followed by the
// same pattern (special variables; `$if` is fine). Hand-written because a
// name is matched several times per statement (lookaheads for `=` and `(`):
// one scan and one keyword test by length instead of eleven string compares.
struct openscad_on {
    using rule_t = openscad_on;
    using subs_t = pg::empty_list;
    template <pg::apply_mode, pg::rewind_mode, template <typename...> class,
              template <typename...> class, typename Input, typename... States>
    static bool match(Input&, States&&... st) {
        return openscad_mode(st...);
    }
};

// Blank space: in OpenSCAD's dialect also the bytes 0xA0 and 0xC2, as
// OpenSCAD 2021.01's lexer reads each (measured): so U+00A0, the no-break
// space (`echo\u00A0("B");`, its test data misc/no-break-space-test.scad),
// and a Latin-1 no-break space (misc/nbsp-latin1-test.scad) are blank;
// kerf's own dialect refuses them.
struct nbsp : pg::seq<openscad_on, pg::one<'\xC2', '\xA0'>> {};
struct blank : pg::plus<pg::sor<pg::one<' ', '\t', '\r', '\n'>, nbsp>> {};
struct ws : pg::star<pg::sor<blank, line_comment, block_comment>> {};

struct name {
    using rule_t = name;
    using subs_t = pg::empty_list;

    static bool first(char c) noexcept { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
    static bool other(char c) noexcept { return first(c) || (c >= '0' && c <= '9'); }
    static bool digit(char c) noexcept { return c >= '0' && c <= '9'; }

    // OpenSCAD's lexer takes the longest token, a number on a tie: `608_dia`
    // and `8bit` are names, `12`, `1e5` and `1.5` numbers. The length of a
    // name starting with a digit at p, or 0 when a number is as long.
    static std::size_t digit_name(const char* p, const char* end) noexcept {
        const char* q = p;
        while (q < end && other(*q)) ++q;
        const char* n = p;
        while (n < end && digit(*n)) ++n;
        if (n < end && *n == '.') {
            ++n;
            while (n < end && digit(*n)) ++n;
        }
        if (n < end && (*n == 'e' || *n == 'E')) {
            const char* x = n + 1;
            if (x < end && (*x == '+' || *x == '-')) ++x;
            if (x < end && digit(*x)) {
                while (x < end && digit(*x)) ++x;
                n = x;
            }
        }
        return q > n ? static_cast<std::size_t>(q - p) : 0;
    }

    template <pg::apply_mode, pg::rewind_mode, template <typename...> class,
              template <typename...> class, typename Input, typename... States>
    static bool match(Input& in, States&&... st) {
        const char* const begin = in.current();
        const char* const end = in.end();
        const char* p = begin;
        const bool special = p < end && *p == '$';
        if (special) ++p;
        if (p < end && digit(*p) && openscad_mode(st...)) {
            const std::size_t n = digit_name(p, end);
            if (n == 0) return false;
            in.bump_in_this_line(static_cast<std::size_t>(p - begin) + n);
            return true;
        }
        if (p == end || !first(*p)) return false;
        const char* const word = p;
        while (++p < end && other(*p)) {
        }
        if (!special && is_keyword(std::string_view(word, static_cast<std::size_t>(p - word)))) return false;
        in.bump_in_this_line(static_cast<std::size_t>(p - begin));
        return true;
    }
};

template <char... Cs>
struct kw : pg::seq<pg::keyword<Cs...>, ws> {};

// ---- numbers ------------------------------------------------------------
// `12 1.5 .5 1. 1e-3 2.5E+4`. Letters, digits or `_` glued to the end
// (`12abc`, `1e`, `0x1F`) are swallowed here and rejected by the action as a
// malformed number located at its first digit.
struct digits : pg::plus<pg::digit> {};
struct exponent : pg::seq<pg::one<'e', 'E'>, pg::opt<pg::one<'+', '-'>>, digits> {};
struct number_lit
    : pg::seq<pg::sor<pg::seq<digits, pg::opt<pg::one<'.'>, pg::star<pg::digit>>>, pg::seq<pg::one<'.'>, digits>>,
              pg::opt<exponent>, pg::star<pg::identifier_other>> {};

// ---- punctuation (each a named rule so a failure can say what it expected)
struct semi : pg::seq<pg::one<';'>, ws> {};
struct comma : pg::seq<pg::one<','>, ws> {};
struct colon : pg::seq<pg::one<':'>, ws> {};
struct lparen : pg::seq<pg::one<'('>, ws> {};
struct rparen : pg::seq<pg::one<')'>, ws> {};
struct lbracket : pg::seq<pg::one<'['>, ws> {};
struct rbracket : pg::seq<pg::one<']'>, ws> {};
struct lbrace : pg::seq<pg::one<'{'>, ws> {};
struct rbrace : pg::seq<pg::one<'}'>, ws> {};
struct assign_eq : pg::seq<pg::one<'='>, pg::not_at<pg::one<'='>>, ws> {};  // `=`, never `==`

}  // namespace kerf::grammar

// The hand-written rules always consume input when they succeed.
template <typename Name>
struct tao::pegtl::analyze_traits<Name, kerf::grammar::block_comment> : tao::pegtl::analyze_any_traits<> {};
template <typename Name>
struct tao::pegtl::analyze_traits<Name, kerf::grammar::string_lit> : tao::pegtl::analyze_any_traits<> {};
template <typename Name>
struct tao::pegtl::analyze_traits<Name, kerf::grammar::name> : tao::pegtl::analyze_any_traits<> {};
template <typename Name>
struct tao::pegtl::analyze_traits<Name, kerf::grammar::openscad_on> : tao::pegtl::analyze_opt_traits<> {};

// The arithmetic, comparison and indexing operators of docs/spec.md §2 on Values.
// Strict: an operator that does not apply to its operands' types (`1 + "a"`,
// `undef * 2`, vectors of different lengths) is a located error, where
// OpenSCAD would warn and yield undef. Those errors are SoftErrors; the
// OpenSCAD dialect answers them with openscad_ops.hpp instead.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "grammar/source.hpp"
#include "interpreter/value.hpp"

namespace kerf {

// Bounds the number of values one operation may create: nested lists share
// structure, so `[l, l] + [l, l]` can stand for exponentially many numbers;
// past `limit` the operation is the error "list size limit N exceeded".
// It also tallies the work the evaluator charges to the step limit: the
// values made (used) and those only read (walked: a dot product's terms, a
// comparison's elements, 1 per 16 bytes of a string compared).
struct OpBudget {
    std::uint64_t limit;
    std::uint64_t used = 0;
    std::uint64_t walked = 0;
    // Where the step limit is reached (used + walked, the evaluator's
    // units): a long loop inside one operation (a matrix product) stops
    // there with WorkCapReached instead of running to its end first.
    std::uint64_t work_cap = UINT64_MAX;

    // n more values made: past limit, "list size limit N exceeded".
    void make(std::uint64_t n, const SourceLoc& loc);
    void walk(std::uint64_t n) { walked += n; }
};

// Thrown past a work cap (OpBudget::work_cap, WorkTally::cap): the
// evaluator answers it with its step limit error.
struct WorkCapReached {};

// The values in v's list tree (0 for anything else), each shared sublist
// counted where it occurs: past budget.limit, "list size limit N exceeded",
// before anything walks an exponentially large operand.
std::uint64_t checked_tree_size(OpBudget& budget, const Value& v, const SourceLoc& loc);

// op is one of "-", "+" (unary).
Value unary_op(std::string_view op, const Value& a, const SourceLoc& loc, OpBudget* budget = nullptr);

// x op y for op one of "+ - * / % ^": binary_op's answer for two numbers
// (the evaluator's way around binary_op for them: no budget, no dispatch on
// the operator's text).
double number_op(char op, double x, double y);

// op is one of "+ - * / % ^ < <= > >= == !=" (&& and || short-circuit in the
// evaluator).
Value binary_op(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, OpBudget* budget = nullptr);

// list[i], string[i] (one UTF-8 character), range[i]. The index must be an
// integral number inside the bounds: out of range is an error (kerf is
// strict; OpenSCAD yields undef).
Value index_value(const Value& object, const Value& index, const SourceLoc& loc);

// A string's characters as OpenSCAD 2021 walks them (glib's
// g_utf8_next_char and g_utf8_strlen): the lead byte alone gives the
// length (0xC0-0xDF two bytes, 0xE0-0xEF three, 0xF0-0xF7 four, 0xF8-0xFB
// five, 0xFC-0xFD six, any other one), and a last character the end cuts
// short is none. On UTF-8 these are the code points; on the Latin-1 bytes
// a .scad file may hold they are OpenSCAD's pieces (measured: "\xA4\xC4\xD6"
// is "\xA4" and "\xC4\xD6", len("\xA4\xC4") is 1). len(), for, s[i] and
// search() all see these same characters.
std::vector<std::string_view> characters(std::string_view s);

// Their number, as OpenSCAD's len().
std::size_t utf8_length(std::string_view s);

// The i-th of them, or nullopt past the end.
std::optional<std::string_view> character_at(std::string_view s, std::size_t i);

// True when s is well-formed UTF-8 (what OpenSCAD's ord() asks).
bool valid_utf8(std::string_view s);

}  // namespace kerf

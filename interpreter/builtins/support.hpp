// Shared plumbing of the built-in functions (builtins_*.cpp): the name table
// each file contributes and the argument checks that turn a wrong call into
// a located SourceError ("sqrt: expected a number, got string") — kerf is
// strict where OpenSCAD returns undef with a warning.
#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "interpreter/builtins/builtins.hpp"

namespace kerf::builtin {

using Entry = Builtin;

// The tables of each group (defined in builtins_math/list/string.cpp).
std::span<const Entry> math_entries();
std::span<const Entry> list_entries();
std::span<const Entry> string_entries();
std::span<const Entry> openscad_entries();  // the rest of OpenSCAD 2021's functions

// A wrong call: a SoftError, so the OpenSCAD dialect makes it undef and a
// warning. A limit is a plain SourceError in every dialect.
[[noreturn]] void fail(const BuiltinContext& ctx, std::string message);

// Checks min <= args.size() <= max: "pow: expected 2 arguments, got 1".
void expect_count(std::span<const Value> args, const BuiltinContext& ctx, std::string_view fn,
                  std::size_t min, std::size_t max);
inline void expect_count(std::span<const Value> args, const BuiltinContext& ctx, std::string_view fn,
                         std::size_t n) {
    expect_count(args, ctx, fn, n, n);
}

// args[i] as a number, or "fn: expected a number, got string" (with
// "argument i+1: " when the function takes several arguments).
double number_arg(std::span<const Value> args, std::size_t i, const BuiltinContext& ctx, std::string_view fn);

// Spells what a value is for messages: "a number", "a string", "undef"...
std::string describe(const Value& v);

}  // namespace kerf::builtin

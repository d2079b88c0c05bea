// What OpenSCAD 2021 answers where kerf's strict operators refuse
// (docs/openscad.md "Operators"): used only by the OpenSCAD dialect, after
// binary_op/unary_op threw a SoftError, and for every index there (OpenSCAD
// indexes a range as [begin, step, end] and truncates a fractional index).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "interpreter/operators.hpp"
#include "interpreter/value.hpp"

namespace kerf {

// OpenSCAD's names in "undefined operation (number + string)": undefined,
// bool, number, string, vector, range.
const char* openscad_type_name(const Value& v);

// `a op b` as OpenSCAD computes it: lists compare lexicographically, + and -
// of lists of unequal length stop at the shorter one, anything else that
// does not apply is undef. `warning` receives what OpenSCAD prints (empty:
// nothing), e.g. "undefined operation (number + string)". The values made
// and walked go to budget (the step limit's charge, operators.hpp), which
// also refuses exponentially large shared lists.
Value openscad_binary(std::string_view op, const Value& a, const Value& b, const SourceLoc& loc, std::string& warning,
                      OpBudget& budget);

// Unary minus: a list negates element-wise (non-numbers become undef), any
// other non-number is undef and "undefined operation (-string)".
Value openscad_unary(std::string_view op, const Value& a, const SourceLoc& loc, std::string& warning, OpBudget& budget);

// object[index]: the element at the truncated index, a range's begin, step
// or end for 0, 1, 2, and undef (silently, as OpenSCAD) for anything else.
Value openscad_index(const Value& object, const Value& index);

// OpenSCAD's RangeType::numValues(): the elements it counts in a range, as
// an unsigned 32-bit number (a step of 0 or an infinite bound is
// 4294967295), which its loops compare with their caps below.
std::uint32_t openscad_range_count(const Range& r);
// A range of this many elements or more runs no `for` or `each` pass, with
// "Bad range parameter in for statement: too many elements (N)" (current
// OpenSCAD's cap for both; 2021.01 caps the `for` statement at 10,000).
inline constexpr std::uint32_t kOpenScadForCap = 1'000'000;
// ... and picks no child in children(range) ("... for children ...").
inline constexpr std::uint32_t kOpenScadChildrenCap = 10'000;

}  // namespace kerf

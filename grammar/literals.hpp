// Decoding of number and string literals (docs/spec.md §1), separate from the
// grammar so it can be tested on its own.
#pragma once
#include <optional>
#include <cstdint>
#include <string>
#include <string_view>

namespace kerf::grammar {

// Value of a number literal as matched by number_lit (`12`, `1.5`, `.5`,
// `1.`, `1e-3`, `2.5E+4`); nullopt if letters, digits or `_` trail it
// (`12abc`, `1e`). Out-of-range literals follow IEEE: `1e999` is +inf,
// `1e-999` is 0.
std::optional<double> parse_number(std::string_view text);

// The text of a string literal given with its quotes; the grammar has
// already rejected escapes other than \" \\ \n \t \r (and, in the
// OpenSCAD dialect, \xNN \uNNNN \UNNNNNN).
std::string decode_string(std::string_view literal);

// Appends code point c (below 0x110000) as UTF-8.
void append_utf8(std::string& out, std::uint32_t c);

}  // namespace kerf::grammar

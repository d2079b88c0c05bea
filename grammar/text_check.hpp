// Byte-level screening of a script before parsing: the source must be UTF-8
// text (docs/spec.md §1, §8). Binary garbage is rejected up front with one located
// error instead of confusing the grammar.
#pragma once
#include <cstddef>
#include <string_view>

namespace kerf::grammar {

// Offset of the first byte that is not part of well-formed UTF-8 (no
// overlong forms, no surrogates, at most U+10FFFF) or is a control
// character other than tab, line feed and carriage return (NUL, DEL, ...);
// npos if the whole text is fine.
std::size_t find_invalid_byte(std::string_view text);

}  // namespace kerf::grammar

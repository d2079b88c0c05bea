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
// npos if the whole text is fine. With `any_high_byte` (the OpenSCAD
// dialect, whose files may be Latin-1: OpenSCAD 2021.01 reads their bytes
// as they are) every byte from 0x80 up passes; control characters do not.
std::size_t find_invalid_byte(std::string_view text, bool any_high_byte = false);

// Length of the well-formed UTF-8 sequence at text[i] (RFC 3629: no
// overlong forms, no surrogates, nothing above U+10FFFF), or 0 if there is
// none there.
std::size_t utf8_sequence_length(std::string_view text, std::size_t i);

}  // namespace kerf::grammar

// Adler-32 (RFC 1950) 16 bytes at a time: zlib's adler32() goes byte by
// byte, and a 2048² PNG's pieces checksum 12.6 MB of filtered rows (0.7 %
// of spheres_100000's CPU at 2048², ~2 % of a one-sphere render's).
#pragma once
#include <cstddef>
#include <cstdint>

namespace kerf::render {

// The Adler-32 of `size` bytes at `data` continuing `adler` (1 for none):
// the value zlib's adler32(adler, data, size) returns.
std::uint32_t adler32_fast(std::uint32_t adler, const std::uint8_t* data, std::size_t size);

}  // namespace kerf::render

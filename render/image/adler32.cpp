#include "render/image/adler32.hpp"

#include <algorithm>

#include <emmintrin.h>

namespace kerf::render {

namespace {

constexpr std::uint64_t kBase = 65521;  // the largest prime below 2^16
// Blocks of whole 16-byte chunks, reduced modulo kBase after each: zlib's
// NMAX (5552) rounded down. The 32-bit lanes below would overflow only
// past ~32 KB of 0xFF bytes (test_adler32 fails with blocks of 64 KB).
constexpr std::size_t kBlock = 5552 / 16 * 16;

std::uint64_t lanes_sum(__m128i v) {
    alignas(16) std::uint32_t lane[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(lane), v);
    return std::uint64_t(lane[0]) + lane[1] + lane[2] + lane[3];
}

}  // namespace

std::uint32_t adler32_fast(std::uint32_t adler, const std::uint8_t* data, std::size_t size) {
    std::uint64_t s1 = adler & 0xffff, s2 = adler >> 16;
    const __m128i zero = _mm_setzero_si128();
    // A byte at offset i of a chunk adds (16 - i) times itself to s2, and
    // every later chunk adds the chunk's sum 16 times more.
    const __m128i first_half = _mm_setr_epi16(16, 15, 14, 13, 12, 11, 10, 9);
    const __m128i second_half = _mm_setr_epi16(8, 7, 6, 5, 4, 3, 2, 1);
    while (size >= 16) {
        const std::size_t block = std::min(size, kBlock) & ~std::size_t(15);
        __m128i sums = zero;      // byte sums (two 64-bit lanes from psadbw)
        __m128i earlier = zero;   // per chunk, the byte sums of the chunks before it
        __m128i weighted = zero;  // the (16 - i) weighted sums
        for (std::size_t at = 0; at < block; at += 16) {
            const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + at));
            earlier = _mm_add_epi32(earlier, sums);
            sums = _mm_add_epi32(sums, _mm_sad_epu8(bytes, zero));
            weighted = _mm_add_epi32(weighted, _mm_madd_epi16(_mm_unpacklo_epi8(bytes, zero), first_half));
            weighted = _mm_add_epi32(weighted, _mm_madd_epi16(_mm_unpackhi_epi8(bytes, zero), second_half));
        }
        s2 += s1 * block + 16 * lanes_sum(earlier) + lanes_sum(weighted);
        s1 += lanes_sum(sums);
        s1 %= kBase, s2 %= kBase;
        data += block, size -= block;
    }
    for (std::size_t i = 0; i < size; ++i) s1 += data[i], s2 += s1;
    s1 %= kBase, s2 %= kBase;
    return std::uint32_t(s2 << 16 | s1);
}

}  // namespace kerf::render

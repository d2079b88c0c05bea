// adler32_fast against zlib's adler32 (the checksum every PNG reader
// checks): random bytes and all-0xFF runs (the largest sums, where a block
// too long overflows a lane), at every length up to a few chunks
// and across block edges, from a fresh start and continuing a running value.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include <zlib.h>

#include "render/image/adler32.hpp"

using namespace kerf::render;

namespace {

std::uint32_t zlib_adler(std::uint32_t start, const std::vector<std::uint8_t>& v, std::size_t from, std::size_t n) {
    return std::uint32_t(adler32(start, v.data() + from, uInt(n)));
}

}  // namespace

TEST_CASE("adler32_fast equals zlib's adler32", "[image][adler32]") {
    std::mt19937 rng(18);
    std::vector<std::uint8_t> noise(40000), full(40000, 0xFF);
    for (auto& b : noise) b = std::uint8_t(rng());
    int mismatches = 0;
    for (const auto* bytes : {&noise, &full}) {
        std::vector<std::size_t> lengths;
        for (std::size_t n = 0; n <= 100; ++n) lengths.push_back(n);
        for (std::size_t n : {5535, 5536, 5537, 5551, 5552, 5553, 11072, 11089, 16384, 39999, 40000})
            lengths.push_back(n);
        for (std::size_t n : lengths)
            for (std::size_t from : {std::size_t(0), std::size_t(3)}) {
                if (from + n > bytes->size()) continue;
                if (adler32_fast(1, bytes->data() + from, n) != zlib_adler(1, *bytes, from, n)) ++mismatches;
                // Continuing a running value near the modulus.
                const std::uint32_t start = 0xFFF0FFF0u;
                if (adler32_fast(start, bytes->data() + from, n) != zlib_adler(start, *bytes, from, n)) ++mismatches;
            }
    }
    CHECK(mismatches == 0);
}

#include <catch2/catch.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/operators.hpp"

namespace {

// The characters one byte at a time, by the lead byte's rule (operators.hpp,
// characters()), without the 8-byte ASCII skip len() and s[i] take.
std::vector<std::string> plain_characters(std::string_view s) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        const std::size_t n = c < 0xC0 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : c < 0xF8 ? 4 : c < 0xFC ? 5 : c < 0xFE ? 6 : 1;
        if (n > s.size() - i) break;  // a last character cut short is none
        out.emplace_back(s.substr(i, n));
        i += n;
    }
    return out;
}

}  // namespace

TEST_CASE("len and s[i] skip ASCII 8 bytes at a time and count as a plain walk does", "[limits]") {
    // Runs of 0 to 19 ASCII bytes (inside, at and past the 8-byte words)
    // before a character that is not ASCII, a lone continuation byte,
    // truncated or invalid sequences, then more ASCII.
    const std::vector<std::string> tails = {"\xC3\xA9",  "\xE2\x82\xAC", "\xF0\x9F\x98\x80", "\xA4",
                                            "\xE2\x82",  "\xF0",         "\xFF\xFE",         "\xC3\xA9xyz0123456789",
                                            "\x80\x80",  ""};
    int checked = 0;
    for (std::size_t k = 0; k < 20; ++k)
        for (const std::string& tail : tails)
            for (const std::string& after : {std::string(), std::string("abcdefghijk")}) {
                const std::string s = std::string(k, 'a') + std::string(k % 3, 'Z') + tail + after;
                const std::vector<std::string> want = plain_characters(s);
                INFO("k " << k << ", " << s.size() << " bytes");
                REQUIRE(kerf::utf8_length(s) == want.size());
                for (std::size_t i = 0; i <= want.size() + 1; ++i) {
                    const std::optional<std::string_view> got = kerf::character_at(s, i);
                    if (i < want.size()) {
                        REQUIRE(got.has_value());
                        CHECK(std::string(*got) == want[i]);
                    } else {
                        CHECK(!got.has_value());
                    }
                    ++checked;
                }
            }
    CHECK(checked > 1000);
}

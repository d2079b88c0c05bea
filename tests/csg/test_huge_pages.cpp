// csg::reserve_huge: the big arrays' reservation on huge pages (a hint the
// kernel may ignore), which must behave as std::vector::reserve does.
#include <catch2/catch.hpp>

#include <cstdint>
#include <memory>
#include <vector>

#include "csg/huge_pages.hpp"

using kerf::csg::reserve_huge;

TEST_CASE("reserve_huge keeps the elements already there, in order", "[memory]") {
    // Elements that own memory: moved into the new buffer, not copied or lost.
    std::vector<std::unique_ptr<int>> v;
    for (int i = 0; i < 1000; ++i) v.push_back(std::make_unique<int>(i));
    const int* first = v.front().get();
    reserve_huge(v, 1 << 20);  // 8 MiB: whole huge pages inside
    REQUIRE(v.size() == 1000);
    CHECK(v.capacity() >= (1u << 20));
    CHECK(v.front().get() == first);
    for (int i = 0; i < 1000; ++i) CHECK(*v[i] == i);
    // The reserved room is used without another move.
    const auto* data = v.data();
    for (int i = 1000; i < (1 << 20); ++i) v.push_back(nullptr);
    CHECK(v.data() == data);
}

TEST_CASE("reserve_huge of an empty vector, or of less than its capacity", "[memory]") {
    std::vector<std::uint64_t> v;
    reserve_huge(v, 3u << 20);
    CHECK(v.empty());
    CHECK(v.capacity() >= (3u << 20));
    v.assign(10, 7);
    const auto* data = v.data();
    reserve_huge(v, 100);  // already room: nothing moves
    CHECK(v.data() == data);
    CHECK(v == std::vector<std::uint64_t>(10, 7));
}

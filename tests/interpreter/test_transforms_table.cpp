// graph::Transforms (interpreter/scene_graph.hpp) keeps a translation as its
// offset alone: every matrix must come back bit for bit, whatever its kind,
// after set() changes a kind and after resize() rolls some back.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "interpreter/scene_graph.hpp"

namespace {

bool same_bits(const glm::dmat4& a, const glm::dmat4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

glm::dmat4 translation(double x, double y, double z) { return glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z)); }

}  // namespace

TEST_CASE("Transforms returns every stored matrix bit for bit") {
    std::vector<glm::dmat4> kept;
    kept.push_back(translation(0.1, -2.5e300, 3e-310));                              // subnormal offset
    kept.push_back(glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(1, 2, 3)));           // general
    kept.push_back(glm::scale(glm::dmat4(1.0), glm::dvec3(2, 1, 1)));                 // general
    glm::dmat4 negative_zero = translation(1, 2, 3);
    negative_zero[0][1] = -0.0;  // == 0, but other bits: must not be taken for the identity
    kept.push_back(negative_zero);
    glm::dmat4 projective = translation(1, 2, 3);
    projective[2][3] = 0.5;  // a last row other than (0, 0, 0, 1)
    kept.push_back(projective);
    kept.push_back(glm::dmat4(1.0));
    kerf::graph::Transforms t;
    for (const glm::dmat4& m : kept) t.push_back(m);
    REQUIRE(t.size() == kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i) {
        INFO("transform " << i);
        CHECK(same_bits(t[i], kept[i]));
        CHECK(same_bits(t.at(i), kept[i]));
    }
    CHECK_THROWS_AS(t.at(kept.size()), std::out_of_range);

    SECTION("set() may change a translation into a general matrix and back") {
        t.set(0, kept[1]);
        t.set(1, translation(4, 5, 6));
        t.set(5, translation(7, 8, 9));
        CHECK(same_bits(t[0], kept[1]));
        CHECK(same_bits(t[1], translation(4, 5, 6)));
        CHECK(same_bits(t[5], translation(7, 8, 9)));
        for (std::size_t i = 2; i < 5; ++i) CHECK(same_bits(t[i], kept[i]));
    }
    SECTION("resize() drops the last ones and the rest stay") {
        t.resize(2);
        REQUIRE(t.size() == 2);
        t.push_back(translation(-1, -2, -3));
        t.push_back(kept[2]);
        CHECK(same_bits(t[0], kept[0]));
        CHECK(same_bits(t[1], kept[1]));
        CHECK(same_bits(t[2], translation(-1, -2, -3)));
        CHECK(same_bits(t[3], kept[2]));
    }
}

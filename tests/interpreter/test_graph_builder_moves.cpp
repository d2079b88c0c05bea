// The builder's arrays past 16K entries are watched by a thread that faults
// their pages in ahead (csg/populate_ahead.hpp). The thread must never touch
// a block an array has left: every push goes through the builder, which
// stops the thread before a push that would move a watched array (past its
// reservation's cap, or a wide insert bigger than the room left). A move
// under a running thread is counted at the writer's next report
// (PopulateAhead::moved_under_thread), so each case pushes past one.
#include <catch2/catch.hpp>

#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "interpreter/graph_builder.hpp"

using kerf::eval::GraphBuilder;

namespace {

// Pushes `push(n)` n elements at a time: to 16K + 1 (the array reserved at
// `cap` and watched), to the cap (still watched), past it by `over` (the
// array moves: the thread was stopped first), then past the next report,
// where a move under a running thread would be counted.
template <class Push, class Capacity>
void past_the_cap(GraphBuilder& b, std::size_t cap, std::size_t over, Push&& push, Capacity&& capacity) {
    push(16384);
    CHECK_FALSE(b.populate_ahead.running());  // not yet reserved
    push(1);
    REQUIRE(capacity() == cap);
    CHECK(b.populate_ahead.running());
    push(cap - 16385);  // exactly fills it
    CHECK(b.populate_ahead.running());
    push(over);
    CHECK_FALSE(b.populate_ahead.running());
    push(16384);  // past the next report; the thread is not started again
    CHECK_FALSE(b.populate_ahead.running());
    CHECK(b.populate_ahead.moved_under_thread() == 0);
}

}  // namespace

TEST_CASE("the page thread stops before a watched node array moves past its cap", "[memory]") {
    GraphBuilder b;
    b.populate_ahead.enable();
    b.max_nodes = 60000;
    past_the_cap(
        b, 60000, 1, [&](std::size_t n) { for (std::size_t i = 0; i < n; ++i) b.add(kerf::graph::Node{}); },
        [&] { return b.graph.nodes.capacity(); });
    CHECK(b.graph.nodes.size() == 60000 + 1 + 16384);
}

TEST_CASE("the page thread stops before a wide child insert outgrows the room left", "[memory]") {
    GraphBuilder b;
    b.populate_ahead.enable();
    b.max_nodes = 60000;
    const std::vector<std::uint32_t> ids(60000, 7);
    past_the_cap(
        b, 60000, 2, [&](std::size_t n) { b.add_child_refs(ids.data(), n); },  // two past the room at once
        [&] { return b.graph.child_refs.capacity(); });
    CHECK(b.graph.child_refs.size() == 60000 + 2 + 16384);
}

TEST_CASE("the page thread stops before the transforms move past their cap", "[memory]") {
    GraphBuilder b;
    b.populate_ahead.enable();
    b.max_matrices = 30000;
    const glm::dmat4 shift = glm::translate(glm::dmat4(1), glm::dvec3(1, 2, 3));
    past_the_cap(
        b, 30000, 1, [&](std::size_t n) { for (std::size_t i = 0; i < n; ++i) b.add_matrix(shift); },
        [&] { return b.graph.matrices.capacity(); });
    CHECK(b.graph.matrices.size() == 30000 + 1 + 16384);
    CHECK(b.graph.matrices[30000] == shift);
}

// linear_extrude's taper replaces transforms in place (set_matrix); a
// general matrix turned into a translation appends its offset to a
// watched array, which must not move under the thread either.
TEST_CASE("the page thread stops before a replaced transform's offset outgrows the room left", "[memory]") {
    GraphBuilder b;
    b.populate_ahead.enable();
    b.max_matrices = 30000;
    const glm::dmat4 shift = glm::translate(glm::dmat4(1), glm::dvec3(1, 2, 3));
    const glm::dmat4 turn = glm::rotate(glm::dmat4(1), 0.5, glm::dvec3(0, 0, 1));
    for (int i = 0; i < 16385; ++i) b.add_matrix(shift);  // reserved at the cap and watched
    for (int i = 16385; i < 30000; ++i) b.add_matrix(turn);
    REQUIRE(b.graph.matrices.offset_array().capacity() == 30000);
    CHECK(b.populate_ahead.running());
    for (std::size_t i = 16385; i < 30000; ++i) b.set_matrix(i, shift);  // the offsets exactly full
    REQUIRE(b.graph.matrices.offset_array().size() == 30000);
    CHECK(b.populate_ahead.running());
    // Back and forth: each return to a translation appends an offset; the
    // first moves the array (the thread stopped first), the rest pass the
    // next report.
    for (int k = 0; k < 4096; ++k) {
        b.set_matrix(7, turn);
        b.set_matrix(7, shift);
    }
    CHECK_FALSE(b.populate_ahead.running());
    CHECK(b.populate_ahead.moved_under_thread() == 0);
    CHECK(b.graph.matrices[7] == shift);
    CHECK(b.graph.matrices[29999] == shift);
}

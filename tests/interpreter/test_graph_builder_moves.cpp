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

void add_nodes(GraphBuilder& b, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) b.add(kerf::graph::Node{});
}

}  // namespace

TEST_CASE("the page thread stops before a watched node array moves past its cap", "[memory]") {
    GraphBuilder b;
    b.populate_ahead.enable();
    b.max_nodes = 60000;
    add_nodes(b, 16384);
    CHECK_FALSE(b.populate_ahead.running());  // not yet reserved
    add_nodes(b, 1);                          // reserved at the cap and watched
    CHECK(b.graph.nodes.capacity() == 60000);
    CHECK(b.populate_ahead.running());
    add_nodes(b, 60000 - b.graph.nodes.size());
    const void* block = b.graph.nodes.data();
    CHECK(b.populate_ahead.running());  // full, not moved
    add_nodes(b, 1);                    // moves: the thread was stopped first
    CHECK(b.graph.nodes.data() != block);
    CHECK_FALSE(b.populate_ahead.running());
    add_nodes(b, 100000);  // and is not started again
    CHECK_FALSE(b.populate_ahead.running());
    CHECK(b.populate_ahead.moved_under_thread() == 0);
    CHECK(b.graph.nodes.size() == 160001);
}

TEST_CASE("the page thread stops before a wide child insert outgrows the room left", "[memory]") {
    GraphBuilder b;
    b.populate_ahead.enable();
    b.max_nodes = 60000;
    std::vector<std::uint32_t> ids(16385, 7);
    b.add_child_refs(ids.data(), 16384);
    b.add_child_refs(ids.data(), 1);  // reserved at the cap and watched
    REQUIRE(b.graph.child_refs.capacity() == 60000);
    CHECK(b.populate_ahead.running());
    b.add_child_refs(ids.data(), 60000 - 16385);  // exactly fills it
    CHECK(b.populate_ahead.running());
    b.add_child_refs(ids.data(), 2);  // two past the room: moves, the thread stopped first
    CHECK_FALSE(b.populate_ahead.running());
    b.add_child_refs(ids.data(), 16384);  // past the next report
    CHECK(b.populate_ahead.moved_under_thread() == 0);
    CHECK(b.graph.child_refs.size() == 76386);
}

TEST_CASE("the page thread stops before the transforms move past their cap", "[memory]") {
    GraphBuilder b;
    b.populate_ahead.enable();
    b.max_matrices = 30000;
    const glm::dmat4 shift = glm::translate(glm::dmat4(1), glm::dvec3(1, 2, 3));
    for (int i = 0; i < 16385; ++i) b.add_matrix(shift);
    REQUIRE(b.graph.matrices.capacity() == 30000);
    CHECK(b.populate_ahead.running());
    for (int i = 16385; i < 30000; ++i) b.add_matrix(shift);
    CHECK(b.populate_ahead.running());
    b.add_matrix(shift);
    CHECK_FALSE(b.populate_ahead.running());
    for (int i = 0; i < 8192; ++i) b.add_matrix(shift);  // past the next report
    CHECK(b.populate_ahead.moved_under_thread() == 0);
    CHECK(b.graph.matrices.size() == 38193);
    CHECK(b.graph.matrices[30000] == shift);
}

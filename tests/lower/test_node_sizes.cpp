// A 10^6-leaf scene holds 2·10^6 graph nodes and 10^6 flat-tree nodes while
// it lowers, so their sizes are memory budgets (docs/performance.md,
// "Memory"), as csg::Leaf's is (tests/csg/test_leaf_size.cpp).
#include <catch2/catch.hpp>

#include "lower/flat_tree.hpp"

TEST_CASE("graph and flat-tree nodes stay within their memory budgets", "[memory]") {
    INFO("sizeof(graph::Node) = " << sizeof(kerf::graph::Node));
    // kinds and flag (4), child run and index (12), parameters (48), source
    // location (24). The flag at the end padded it to 96.
    CHECK(sizeof(kerf::graph::Node) <= 88);
    INFO("sizeof(lowering::TNode) = " << sizeof(kerf::lowering::TNode));
    // operation and seven indices; a copy of each leaf's box made it 80.
    CHECK(sizeof(kerf::lowering::TNode) <= 32);
}

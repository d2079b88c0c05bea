// Structural invariants every lowered scene must satisfy (csg/scene.hpp),
// checked from the arrays alone.
#pragma once
#include <catch2/catch.hpp>

#include <vector>

#include "csg/scene.hpp"

namespace kerf::test {

inline void check_structure(const csg::Scene& s) {
    REQUIRE(!s.materials.empty());
    if (s.root == csg::kNone) {
        CHECK(s.nodes.empty());
        CHECK(s.leaves.empty());
        return;
    }
    REQUIRE(s.root == 0);
    CHECK(s.nodes[0].parent == csg::kNone);
    std::vector<int> leaf_uses(s.leaves.size(), 0), node_uses(s.nodes.size(), 0);
    for (std::uint32_t i = 0; i < s.nodes.size(); ++i) {
        const csg::Node& n = s.nodes[i];
        if (n.op == csg::Op::Leaf) {
            REQUIRE(n.first < s.leaves.size());
            ++leaf_uses[n.first];
            CHECK((n.bounds.lo == s.leaves[n.first].bounds.lo && n.bounds.hi == s.leaves[n.first].bounds.hi));
            continue;
        }
        CHECK(n.count >= 2);  // single-child operations disappear
        REQUIRE(std::size_t(n.first) + n.count <= s.children.size());
        for (std::uint32_t k = 0; k < n.count; ++k) {
            const std::uint32_t c = s.children[n.first + k];
            REQUIRE(c < s.nodes.size());
            CHECK(c > i);  // pre-order
            CHECK(s.nodes[c].parent == i);
            ++node_uses[c];
            const csg::Node& cn = s.nodes[c];
            // flattened: no union directly in a union, no intersection in an intersection
            if (n.op != csg::Op::Difference) CHECK(cn.op != n.op);
            if (n.op == csg::Op::Difference && k > 0) CHECK(cn.op != csg::Op::Union);
            if (n.op == csg::Op::Difference && k == 0) CHECK(cn.op != csg::Op::Difference);
        }
        CHECK(!n.bounds.empty());
    }
    for (std::uint32_t i = 1; i < s.nodes.size(); ++i) CHECK(node_uses[i] == 1);
    for (int u : leaf_uses) CHECK(u == 1);
    for (const csg::Leaf& l : s.leaves) CHECK(l.material < s.materials.size());
}

}  // namespace kerf::test

// Identical leaves among the operands of one operation are one operand
// (docs/lowering.md, "Duplicate leaves"): A ∪ A = A, A ∩ A = A, and
// M − A − A = M − A. Identical means the same bits: kind, parameters,
// transform, material, pattern frame and mesh (the source location does
// not matter).
// 100,000 coincident spheres cost every ray through them 100,000 interval
// tests; after this they cost one.
#pragma once
#include <cstdint>
#include <vector>

#include "lower/flat_tree.hpp"

namespace kerf::lowering {

// The hash of the bits that decide equality, kept in TNode::hash when the
// leaf is made (while it is in cache: reading every leaf again cost +25%
// of lowering a million-leaf union).
std::uint32_t leaf_hash(const csg::Leaf& leaf);

// Unlinks every leaf of the list head..tail (linked through TNode::next)
// equal to an earlier one; returns the new count and updates head/tail.
// `count` must be at least the list's length: it sizes the table (a
// smaller one would fill, and a probe would never end).
// From kParallelDuplicates leaves on, `threads` (0: one per hardware
// thread) take half of them each; the same leaves go.
constexpr std::uint32_t kParallelDuplicates = 8192;
std::uint32_t drop_duplicate_leaves(std::vector<TNode>& nodes, const std::vector<csg::Leaf>& leaves,
                                    std::uint32_t& head, std::uint32_t& tail, std::uint32_t count,
                                    unsigned threads = 1);

}  // namespace kerf::lowering

#include "lower/duplicate_leaves.hpp"

#include <cstring>

namespace kerf::lowering {

namespace {

// The fields that decide what a leaf is, as one block of bits.
struct LeafBits {
    double p[6];
    double linear[9];
    double offset[3];
    std::uint32_t material, mesh, polygon, kind;
    std::uint32_t frame;  // the pattern's frame: the same sphere in another pattern frame looks different
};

LeafBits bits(const csg::Leaf& l) {
    LeafBits b;
    std::memset(&b, 0, sizeof b);
    std::memcpy(b.p, l.p, sizeof b.p);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) b.linear[3 * c + r] = l.object_from_world.linear[c][r];
    for (int i = 0; i < 3; ++i) b.offset[i] = l.object_from_world.offset[i];
    b.material = l.material;
    b.mesh = l.mesh;
    b.polygon = l.polygon;  // prisms: the section
    b.kind = std::uint32_t(l.kind);
    b.frame = l.material_frame;  // equal indices iff equal frames (lower/material_frames.hpp)
    return b;
}

std::uint64_t hash_of(const LeafBits& b) {
    std::uint64_t w[sizeof(LeafBits) / 8];
    std::memcpy(w, &b, sizeof w);
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t x : w) {
        h ^= x + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdull;
    }
    return h ^ (h >> 32);
}

}  // namespace

std::uint32_t leaf_hash(const csg::Leaf& leaf) { return static_cast<std::uint32_t>(hash_of(bits(leaf))); }

std::uint32_t drop_duplicate_leaves(std::vector<TNode>& nodes, const std::vector<csg::Leaf>& leaves,
                                    std::uint32_t& head, std::uint32_t& tail, std::uint32_t count) {
    std::uint32_t leaf_count = 0;
    for (std::uint32_t c = head; c != csg::kNone; c = nodes[c].next) leaf_count += nodes[c].op == csg::Op::Leaf;
    if (leaf_count < 2) return count;
    // Open addressing over the list's leaves (a node-based set doubled the
    // cost of lowering a million-leaf union).
    std::size_t size = 4;
    while (size < 2 * std::size_t(leaf_count)) size *= 2;
    std::vector<std::uint32_t> slots(size, csg::kNone);
    std::uint32_t prev = csg::kNone;
    for (std::uint32_t c = head; c != csg::kNone;) {
        const std::uint32_t next = nodes[c].next;
        bool duplicate = false;
        if (nodes[c].op == csg::Op::Leaf) {
            std::size_t i = nodes[c].hash & (size - 1);
            for (; slots[i] != csg::kNone; i = (i + 1) & (size - 1)) {
                if (nodes[slots[i]].hash != nodes[c].hash) continue;
                const LeafBits x = bits(leaves[nodes[slots[i]].leaf]), y = bits(leaves[nodes[c].leaf]);
                if (std::memcmp(&x, &y, sizeof x) == 0) {
                    duplicate = true;
                    break;
                }
            }
            if (!duplicate) slots[i] = c;
        }
        if (duplicate) {
            if (prev == csg::kNone) head = next; else nodes[prev].next = next;
            if (tail == c) tail = prev;
            nodes[c].next = csg::kNone;
            --count;
        } else {
            prev = c;
        }
        c = next;
    }
    return count;
}

}  // namespace kerf::lowering

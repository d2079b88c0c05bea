#include "lower/duplicate_leaves.hpp"

#include <bit>
#include <cassert>
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

}  // namespace

// The same bits as LeafBits, read in place: building the block first (its
// memset and copies) was most of the 290 instructions a leaf this cost.
// Equal bits give equal hashes; nothing else depends on its values.
std::uint32_t leaf_hash(const csg::Leaf& l) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    const auto mix = [&h](std::uint64_t x) {
        h = (h ^ x) * 0xff51afd7ed558ccdull;
        h ^= h >> 32;
    };
    const auto mix_double = [&mix](double d) { mix(std::bit_cast<std::uint64_t>(d)); };
    for (double p : l.p) mix_double(p);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) mix_double(l.object_from_world.linear[c][r]);
    for (int i = 0; i < 3; ++i) mix_double(l.object_from_world.offset[i]);
    mix(std::uint64_t(l.material) | std::uint64_t(l.mesh) << 32);
    mix(std::uint64_t(l.polygon) | std::uint64_t(l.kind) << 32);
    mix(l.material_frame);
    h *= 0xc4ceb9fe1a85ec53ull;  // the low bits pick the slot: spread the high ones into them
    return static_cast<std::uint32_t>(h ^ (h >> 29));
}

std::uint32_t drop_duplicate_leaves(std::vector<TNode>& nodes, const std::vector<csg::Leaf>& leaves,
                                    std::uint32_t& head, std::uint32_t& tail, std::uint32_t count) {
    if (count < 2) return count;
    // Open addressing over the list's leaves (a node-based set doubled the
    // cost of lowering a million-leaf union), sized by the whole list: a
    // walk to count its leaves first was a fifth of this.
    std::size_t size = 4;
    while (size < 2 * std::size_t(count)) size *= 2;
    // A slot holds the hash beside the node, so a probe reads no node (they
    // lie anywhere in the tree's array: a cache miss a probe at 10^5 leaves).
    // (node + 1: an empty slot is 0, so the table is zeroed memory.)
    constexpr std::uint64_t kEmpty = 0;
    std::vector<std::uint64_t> slots(size, kEmpty);
    std::uint32_t prev = csg::kNone;
    [[maybe_unused]] std::uint32_t kept = 0;
    for (std::uint32_t c = head; c != csg::kNone;) {
        const std::uint32_t next = nodes[c].next;
        bool duplicate = false;
        if (nodes[c].op == csg::Op::Leaf) {
            const std::uint32_t hash = nodes[c].hash;
            std::size_t i = hash & (size - 1);
            for (; slots[i] != kEmpty; i = (i + 1) & (size - 1)) {
                if (std::uint32_t(slots[i] >> 32) != hash) continue;
                const LeafBits x = bits(leaves[nodes[std::uint32_t(slots[i]) - 1].leaf]), y = bits(leaves[nodes[c].leaf]);
                if (std::memcmp(&x, &y, sizeof x) == 0) {
                    duplicate = true;
                    break;
                }
            }
            if (!duplicate) {
                // count bounds the list's length (the header's contract),
                // so the table stays at most half full and a probe ends.
                assert(++kept <= count && 2 * std::size_t(kept) <= size);
                slots[i] = std::uint64_t(hash) << 32 | (c + 1);
            }
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

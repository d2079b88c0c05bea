#include "lower/duplicate_leaves.hpp"

#include <algorithm>
#include <bit>
#include <iterator>
#include <cassert>
#include <cstring>

#include "lower/parallel_indices.hpp"

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

namespace {

// The slot table of one set of leaves (open addressing over their hashes):
// whether an equal leaf was inserted before, else insert this one.
class LeafTable {
public:
    // `count`: at most that many leaves go in, so it stays at most half full
    // and a probe ends.
    explicit LeafTable(std::uint32_t count) {
        while (size_ < 2 * std::size_t(count)) size_ *= 2;
        slots_.assign(size_, kEmpty);
    }

    bool seen_or_insert(const std::vector<TNode>& nodes, const std::vector<csg::Leaf>& leaves, std::uint32_t c) {
        const std::uint32_t hash = nodes[c].hash;
        std::size_t i = hash & (size_ - 1);
        for (; slots_[i] != kEmpty; i = (i + 1) & (size_ - 1)) {
            if (std::uint32_t(slots_[i] >> 32) != hash) continue;
            const LeafBits x = bits(leaves[nodes[std::uint32_t(slots_[i]) - 1].leaf]), y = bits(leaves[nodes[c].leaf]);
            if (std::memcmp(&x, &y, sizeof x) == 0) return true;
        }
        assert(2 * ++kept_ <= size_);
        slots_[i] = std::uint64_t(hash) << 32 | (c + 1);
        return false;
    }

private:
    // A slot holds the hash beside the node, so a probe reads no node (they
    // lie anywhere in the tree's array: a cache miss a probe at 10^5 leaves).
    // (node + 1: an empty slot is 0, so the table is zeroed memory.)
    static constexpr std::uint64_t kEmpty = 0;
    std::size_t size_ = 4;
    std::vector<std::uint64_t> slots_;
    [[maybe_unused]] std::size_t kept_ = 0;
};

// Unlinks node c (after prev) from the list head..tail.
void unlink(std::vector<TNode>& nodes, std::uint32_t& head, std::uint32_t& tail, std::uint32_t prev, std::uint32_t c) {
    const std::uint32_t next = nodes[c].next;
    if (prev == csg::kNone) head = next; else nodes[prev].next = next;
    if (tail == c) tail = prev;
    nodes[c].next = csg::kNone;
}

// Equal leaves have equal hashes: split by the hash's top bit, each half
// is deduplicated alone, in list order, by its own thread; then the
// duplicates found are unlinked in one pass. The same leaves go as in one
// pass over the whole list.
std::uint32_t drop_in_halves(std::vector<TNode>& nodes, const std::vector<csg::Leaf>& leaves, std::uint32_t& head,
                             std::uint32_t& tail, std::uint32_t count, unsigned threads) {
    std::uint32_t in_half[2] = {0, 0};
    for (std::uint32_t c = head; c != csg::kNone; c = nodes[c].next)
        if (nodes[c].op == csg::Op::Leaf) ++in_half[nodes[c].hash >> 31];
    // The list positions of each half's duplicates (a list per half, not a
    // flag per leaf: most unions have none, and 10^6 flags were 1 MB of peak).
    std::vector<std::uint32_t> duplicates[2];
    for_each_index(2, 1, threads, [&](std::size_t half) {
        LeafTable table(in_half[half]);
        std::uint32_t at = 0;
        for (std::uint32_t c = head; c != csg::kNone; c = nodes[c].next, ++at)
            if (nodes[c].op == csg::Op::Leaf && nodes[c].hash >> 31 == half && table.seen_or_insert(nodes, leaves, c))
                duplicates[half].push_back(at);
    });
    if (duplicates[0].empty() && duplicates[1].empty()) return count;
    std::vector<std::uint32_t> drop;
    std::merge(duplicates[0].begin(), duplicates[0].end(), duplicates[1].begin(), duplicates[1].end(), std::back_inserter(drop));
    drop.push_back(csg::kNone);  // (a position never reached)
    std::uint32_t prev = csg::kNone, at = 0;
    auto next_drop = drop.begin();
    for (std::uint32_t c = head; c != csg::kNone; ++at) {
        const std::uint32_t next = nodes[c].next;
        if (at == *next_drop) {
            unlink(nodes, head, tail, prev, c);
            --count;
            ++next_drop;
        } else {
            prev = c;
        }
        c = next;
    }
    return count;
}

}  // namespace

std::uint32_t drop_duplicate_leaves(std::vector<TNode>& nodes, const std::vector<csg::Leaf>& leaves,
                                    std::uint32_t& head, std::uint32_t& tail, std::uint32_t count, unsigned threads) {
    if (count < 2) return count;
    if (threads != 1 && count >= kParallelDuplicates) return drop_in_halves(nodes, leaves, head, tail, count, threads);
    // Open addressing over the list's leaves (a node-based set doubled the
    // cost of lowering a million-leaf union), sized by the whole list: a
    // walk to count its leaves first was a fifth of this.
    LeafTable table(count);
    std::uint32_t prev = csg::kNone;
    for (std::uint32_t c = head; c != csg::kNone;) {
        const std::uint32_t next = nodes[c].next;
        if (nodes[c].op == csg::Op::Leaf && table.seen_or_insert(nodes, leaves, c)) {
            unlink(nodes, head, tail, prev, c);
            --count;
        } else {
            prev = c;
        }
        c = next;
    }
    return count;
}

}  // namespace kerf::lowering

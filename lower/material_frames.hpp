// The table of pattern frames (csg::Scene::material_frames) while lowering:
// each distinct material_from_world stored once, so a million leaves under
// one material() call share one entry instead of carrying 96 bytes each.
#pragma once
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "csg/scene.hpp"

namespace kerf::lowering {

class MaterialFrames {
public:
    MaterialFrames();  // entry 0: the identity, the frame of every unpatterned leaf

    // The index of the frame material_from_world = invert(world_from_call),
    // added if new. Equal indices mean equal bits, so duplicate-leaf
    // detection may compare indices (lower/duplicate_leaves.*).
    std::uint32_t frame_of_call(const csg::Affine& world_from_call);

    std::vector<csg::Affine> frames;

private:
    using Bits = std::array<std::uint64_t, 12>;
    struct BitsHash {
        std::size_t operator()(const Bits& b) const;
    };
    static Bits bits(const csg::Affine& a);
    std::uint32_t intern(const csg::Affine& frame);

    std::unordered_map<Bits, std::uint32_t, BitsHash> index_;
    // Sibling leaves share their call: the last call's frame answers them
    // without an inversion or a lookup.
    Bits last_call_{};
    std::uint32_t last_index_ = csg::kNone;
};

}  // namespace kerf::lowering

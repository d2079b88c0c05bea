#include "lower/material_frames.hpp"

#include <cstring>

#include "lower/leaf_placement.hpp"

namespace kerf::lowering {

MaterialFrames::MaterialFrames() { intern(csg::Affine{}); }

// The bits of each entry, with −0 read as +0 (x + 0.0): inverting the
// identity gives offset −0, which maps every point as +0 does.
MaterialFrames::Bits MaterialFrames::bits(const csg::Affine& a) {
    Bits b;
    auto put = [&](int i, double v) {
        v += 0.0;
        std::memcpy(&b[i], &v, 8);
    };
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) put(3 * c + r, a.linear[c][r]);
    for (int i = 0; i < 3; ++i) put(9 + i, a.offset[i]);
    return b;
}

std::size_t MaterialFrames::BitsHash::operator()(const Bits& b) const {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::uint64_t x : b) h = (h ^ x) * 0x100000001b3ull ^ (h >> 29);
    return static_cast<std::size_t>(h);
}

std::uint32_t MaterialFrames::intern(const csg::Affine& frame) {
    const auto [it, added] = index_.try_emplace(bits(frame), static_cast<std::uint32_t>(frames.size()));
    if (added) frames.push_back(frame);
    return it->second;
}

std::uint32_t MaterialFrames::frame_of_call(const csg::Affine& world_from_call) {
    const Bits call = bits(world_from_call);
    if (last_index_ != csg::kNone && call == last_call_) return last_index_;
    last_call_ = call;
    last_index_ = intern(invert(world_from_call));
    return last_index_;
}

}  // namespace kerf::lowering

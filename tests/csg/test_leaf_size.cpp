// The leaf is the scene's largest array (one per primitive: 10^6 spheres are
// 10^6 leaves), so its size is a memory budget (docs/performance.md,
// "Memory"): a field every leaf pays for but few use belongs in a shared
// table, as the pattern frame does (Scene::material_frames).
#include <catch2/catch.hpp>

#include "csg/scene.hpp"

TEST_CASE("a leaf stays within its memory budget", "[memory]") {
    INFO("sizeof(csg::Leaf) = " << sizeof(kerf::csg::Leaf));
    // 312 bytes: kind and five indices (24), parameters (48), two affine
    // maps (192) and the box (48). A pattern frame per leaf and a stored
    // normal matrix made it 480.
    CHECK(sizeof(kerf::csg::Leaf) <= 312);
}

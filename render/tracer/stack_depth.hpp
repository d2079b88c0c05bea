// The tracer evaluates the operation tree recursively (spans calls itself
// once per level, through Embree's traversal when a node has its own BVH),
// so a deep tree needs a deep stack. render() measures the scene's depth,
// refuses a tree deeper than csg::kMaxDepth, and makes sure every thread
// that traces has the stack that depth needs: never a stack overflow
// (docs/lowering.md, "Depth").
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>

#include "csg/scene.hpp"

namespace kerf::render {

// Stack per level of the tree, measured on the deepest paths (RelWithDebInfo,
// GCC, x86-64): a difference or intersection evaluated directly ~430 bytes;
// one whose children sit in their own Embree BVH (more than 8 of them, the
// query nests rtcIntersect1 in the callback) ~10,150 bytes. 16 KiB leaves
// room for other compilers and Embree builds.
constexpr std::size_t kStackPerLevel = std::size_t(16) << 10;
// Below the first level: shading, reflection, the top-level traversal.
constexpr std::size_t kStackBase = std::size_t(1) << 20;

// Nodes on the longest root-to-leaf path (0 for an empty scene).
std::uint32_t tree_depth(const csg::Scene& scene);

inline std::size_t stack_needed(std::uint32_t depth) { return kStackBase + std::size_t(depth) * kStackPerLevel; }

// Bytes of stack left below the caller on the current thread.
std::size_t stack_left();

// Runs fn on a new thread with `bytes` of stack (address space, committed
// as touched) and rethrows what it threw.
void run_with_stack(std::size_t bytes, const std::function<void()>& fn);

// Refuses a tree deeper than csg::kMaxDepth (std::runtime_error naming
// `what`, e.g. "renders"), then runs fn(stack_need) where every thread that
// traces has the stack the tree needs: TBB's workers are started with it
// (when this is the process's first query; otherwise a worker with too
// little traces nothing and the query fails with a message), and the
// calling thread is replaced by one with enough if it has too little.
void with_tracer_stack(const csg::Scene& scene, const char* what, const std::function<void(std::size_t)>& fn);

}  // namespace kerf::render

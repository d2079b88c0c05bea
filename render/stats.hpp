// RenderStats: the per-thread ray and operation counters, summed once at
// the end of a render (no shared counters while tracing).
#pragma once
#include <tbb/enumerable_thread_specific.h>

#include "render/render.hpp"
#include "render/shading.hpp"

namespace kerf::render {

RenderStats sum_stats(const tbb::enumerable_thread_specific<ThreadState>& states, double seconds);

}  // namespace kerf::render

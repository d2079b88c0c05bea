#include "render/tracer/stack_depth.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <vector>

#include <string>

#include <pthread.h>
#include <tbb/global_control.h>

namespace kerf::render {

std::uint32_t tree_depth(const csg::Scene& scene) {
    if (scene.root == csg::kNone) return 0;
    // Pre-order: a node's parent comes before it, so one pass suffices.
    std::vector<std::uint32_t> depth(scene.nodes.size(), 0);
    std::uint32_t deepest = 0;
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const std::uint32_t p = scene.nodes[i].parent;
        depth[i] = p == csg::kNone || p >= i ? 1 : depth[p] + 1;
        deepest = std::max(deepest, depth[i]);
    }
    return deepest;
}

std::size_t stack_left() {
    // The lowest address of this thread's stack, asked once per thread
    // (for the main thread glibc reads /proc/self/maps).
    thread_local const char* low = [] {
        pthread_attr_t attr;
        void* addr = nullptr;
        std::size_t size = 0;
        if (pthread_getattr_np(pthread_self(), &attr) == 0) {
            pthread_attr_getstack(&attr, &addr, &size);
            pthread_attr_destroy(&attr);
        }
        return static_cast<const char*>(addr);
    }();
    char here;
    if (!low || &here < low) return 0;  // unknown: assume none, the caller moves to a thread it sized
    return std::size_t(&here - low);
}

void run_with_stack(std::size_t bytes, const std::function<void()>& fn) {
    struct Task {
        const std::function<void()>* fn;
        std::exception_ptr error;
    } task{&fn, nullptr};
    auto body = [](void* p) -> void* {
        auto* t = static_cast<Task*>(p);
        try {
            (*t->fn)();
        } catch (...) {
            t->error = std::current_exception();
        }
        return nullptr;
    };
    pthread_attr_t attr;
    pthread_t thread;
    const bool started = pthread_attr_init(&attr) == 0 && pthread_attr_setstacksize(&attr, bytes) == 0 &&
                         pthread_create(&thread, &attr, body, &task) == 0;
    pthread_attr_destroy(&attr);
    if (!started) throw std::runtime_error("cannot start a render thread with the stack this scene's depth needs");
    pthread_join(thread, nullptr);
    if (task.error) std::rethrow_exception(task.error);
}

void with_tracer_stack(const csg::Scene& scene, const char* what, const std::function<void(std::size_t)>& fn) {
    const std::uint32_t depth = tree_depth(scene);
    if (depth > csg::kMaxDepth)
        throw std::runtime_error("the CSG tree is " + std::to_string(depth) + " levels deep; kerf " + what +
                                 " trees up to " + std::to_string(csg::kMaxDepth) + " levels deep");
    const std::size_t need = stack_needed(depth);
    const std::size_t worker_stack = std::max(need + kStackBase, tbb::global_control::active_value(tbb::global_control::thread_stack_size));
    tbb::global_control stack_size(tbb::global_control::thread_stack_size, worker_stack);
    if (stack_left() >= need) return fn(need);
    run_with_stack(need + kStackBase, [&] { fn(need); });
}

}  // namespace kerf::render

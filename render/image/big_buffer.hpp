// Storage for whole images (a 2048² RGB float image is 50 MB): a
// std::vector allocator that leaves elements uninitialised (the renderer
// writes every one, so zero-filling first was a serial pass over all of it)
// and aligns big blocks to huge pages, advised as such with
// KERF_HUGE_PAGES=1 (csg/huge_pages.hpp: off by default, slower on virtual
// machines). Page faults and the zero-fill were ~8 % of a simple 2048²
// render's CPU time.
#pragma once
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#include "csg/huge_pages.hpp"

namespace kerf::render {

template <typename T>
struct BigBufferAllocator {
    using value_type = T;
    static constexpr std::size_t kHuge = csg::kHugePage;

    BigBufferAllocator() = default;
    template <typename U>
    BigBufferAllocator(const BigBufferAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
        if (bytes < 2 * kHuge) {
            if (void* p = std::malloc(bytes ? bytes : 1)) return static_cast<T*>(p);
            throw std::bad_alloc();
        }
        const std::size_t rounded = (bytes + kHuge - 1) / kHuge * kHuge;
        void* p = std::aligned_alloc(kHuge, rounded);
        if (!p) throw std::bad_alloc();
        csg::advise_huge_pages(p, rounded);  // a hint: failure only costs speed
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t) noexcept { std::free(p); }

    // resize() default-initialises: trivial types stay as they are.
    template <typename U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }

    template <typename U>
    bool operator==(const BigBufferAllocator<U>&) const noexcept { return true; }
    template <typename U>
    bool operator!=(const BigBufferAllocator<U>&) const noexcept { return false; }
};

template <typename T>
using BigVector = std::vector<T, BigBufferAllocator<T>>;

}  // namespace kerf::render

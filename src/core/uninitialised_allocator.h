#pragma once
// An allocator for arrays whose every element is written right after they are sized (the build's
// references and nodes, the wide BVH's nodes and blocks): resize() leaves new elements of plain
// structs of numbers unwritten, their default member values included, so that the memory is first
// touched, and faulted in, by the threads that fill it, and written once rather than twice.
//
// Arrays of kHugePageArrayBytes (256 KiB) or more get memory of their own in transparent huge
// pages (allocateHugePageArray, huge_pages.h), advised before anything touches it: each 2 MiB
// faults in at once instead of in 512 pieces, and is returned to the system when the array is
// freed. Page faults are dear in a virtual machine (about 11 us each in the Zen 5 guest of
// PERFORMANCE.md, "On the Zen 5"), and a build writes tens of megabytes of new arrays: a first
// build of the dragon took 7,000 page faults with them, 26,000 without (220 since its subtrees
// and the 8-wide form's share arrays too: bvh_slot_array.h). Smaller arrays come from the heap.

#include "huge_pages.h"

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace raylab {

template <typename T> struct UninitialisedAllocator {
    using value_type = T;

    UninitialisedAllocator() = default;
    template <typename U> UninitialisedAllocator(const UninitialisedAllocator<U>&) {}

    T* allocate(std::size_t n) {
        if (!inHugePages(n)) {
            return std::allocator<T>{}.allocate(n);
        }
        return static_cast<T*>(allocateHugePageArray(n * sizeof(T)));
    }
    void deallocate(T* data, std::size_t n) {
        if (!inHugePages(n)) {
            std::allocator<T>{}.deallocate(data, n);
            return;
        }
        freeHugePageArray(data, n * sizeof(T));
    }

    // Without arguments, a trivially copyable element is left as its memory holds it, even one
    // with default member values (BvhNode, LeafSpan): such an element is a plain struct of
    // numbers, an implicit-lifetime type, which the allocation itself brings into being.
    template <typename U, typename... Args> void construct(U* p, Args&&... args) {
        if constexpr (sizeof...(Args) == 0) {
            if constexpr (!std::is_trivially_copyable_v<U>) {
                ::new (static_cast<void*>(p)) U;
            }
        } else {
            ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
        }
    }

    template <typename U> bool operator==(const UninitialisedAllocator<U>&) const { return true; }

private:
    // std::vector never asks for more than max_size() elements: n * sizeof(T) does not wrap.
    static bool inHugePages(std::size_t n) { return n * sizeof(T) >= kHugePageArrayBytes; }
};

template <typename T> using UninitialisedVector = std::vector<T, UninitialisedAllocator<T>>;

} // namespace raylab

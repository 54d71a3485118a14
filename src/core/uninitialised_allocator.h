#pragma once
// An allocator whose resize() leaves new elements default-initialised: for plain structs of
// numbers, not written. For arrays whose every element is written right after they are sized
// (the build's references, the wide BVH's nodes and blocks), so that the memory is first
// touched, and faulted in, by the threads that fill it, and written once rather than twice.

#include <memory>
#include <new>
#include <utility>

namespace raylab {

template <typename T> struct UninitialisedAllocator : std::allocator<T> {
    template <typename U> struct rebind { using other = UninitialisedAllocator<U>; };
    UninitialisedAllocator() = default;
    template <typename U> UninitialisedAllocator(const UninitialisedAllocator<U>&) {}
    template <typename U, typename... Args> void construct(U* p, Args&&... args) {
        if constexpr (sizeof...(Args) == 0) {
            ::new (static_cast<void*>(p)) U;
        } else {
            ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
        }
    }
};

} // namespace raylab

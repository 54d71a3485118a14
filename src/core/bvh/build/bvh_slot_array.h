#pragma once
// A growable array in a slot of memory it does not own (internal to core): where the build's
// subtrees together fill whole huge pages (bvh_build.cpp), each takes a part of one array shared
// by them all (uninitialised_allocator.h) instead of growing an array of its own on the heap,
// whose every new 4 KiB page is a page fault (about 11 us each in the Zen 5 guest of
// PERFORMANCE.md). An array that outgrows its slot, or has none, grows in memory of its own, its
// elements copied; the slot is then unused. Elements are plain structs of numbers: resize() leaves
// new ones unwritten.

#include "huge_pages.h"
#include "uninitialised_allocator.h"

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace raylab {

template <typename T> class SlotArray {
public:
    SlotArray() = default; // no slot: grows in memory of its own from the start
    SlotArray(T* slot, std::size_t capacity) : data_(slot), capacity_(capacity) {}
    // Moved, never copied: a copy would share the slot. One moved from is empty, without a slot.
    SlotArray(SlotArray&& o) noexcept
        : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)),
          capacity_(std::exchange(o.capacity_, 0)), own_(std::move(o.own_)) {}
    SlotArray& operator=(SlotArray&& o) noexcept {
        data_ = std::exchange(o.data_, nullptr);
        size_ = std::exchange(o.size_, 0);
        capacity_ = std::exchange(o.capacity_, 0);
        own_ = std::move(o.own_);
        o.own_.clear();
        return *this;
    }
    SlotArray(const SlotArray&) = delete;
    SlotArray& operator=(const SlotArray&) = delete;

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    // True while the elements are still in the slot given at construction.
    bool inSlot() const { return own_.empty(); }
    T* data() { return data_; }
    const T* data() const { return data_; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }

    // Room for n elements at least without moving again.
    void reserve(std::size_t n) {
        if (n > capacity_) {
            grow(n);
        }
    }
    void resize(std::size_t n) {
        reserve(n);
        size_ = n;
    }
    void push_back(const T& value) {
        if (size_ == capacity_) {
            grow(size_ + 1);
        }
        data_[size_++] = value;
    }

private:
    // At least `n` elements, twice the capacity at least (amortised constant push_back).
    void grow(std::size_t n) {
        UninitialisedVector<T> bigger(std::max({n, 2 * capacity_, std::size_t{16}}));
        std::copy(data_, data_ + size_, bigger.begin());
        own_.swap(bigger); // a vector's move or swap keeps its elements where they are
        data_ = own_.data();
        capacity_ = own_.size();
    }

    T* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
    UninitialisedVector<T> own_; // the elements once they outgrew the slot
};

// Where the slots of one shared array lie, one after another: slot i is [begin(i), begin(i + 1)),
// each starting on a 64-byte boundary (no cache line shared by two threads' arrays).
template <typename T> class SlotLayout {
public:
    // A slot of at least `elements`, rounded up to whole cache lines.
    void append(std::size_t elements) {
        ends_.push_back(ends_.back() + (elements + kPerLine - 1) / kPerLine * kPerLine);
    }
    std::size_t begin(std::size_t i) const { return ends_[i]; }
    std::size_t total() const { return ends_.back(); }

private:
    static constexpr std::size_t kPerLine = 64 / std::gcd(std::size_t{64}, sizeof(T));
    std::vector<std::size_t> ends_{0};
};

// Sizes `shared`, the array whose slots `layout` places: all of them where they take huge pages of
// their own (kHugePageArrayBytes or more), else none, each array then growing in memory of its
// own from the start (slotIn). In a smaller array, on the heap, the unused ends of the slots would
// be faulted in too: the thin triangles' first build took 1,070 page faults against 810-900 with
// the subtrees' arrays each on its own.
template <typename T>
void sizeSharedSlots(UninitialisedVector<T>& shared, const SlotLayout<T>& layout) {
    const std::size_t elements = layout.total();
    shared.resize(elements * sizeof(T) >= kHugePageArrayBytes ? elements : 0);
}

// The array in slot i of `shared` (sized by sizeSharedSlots), or, where `shared` is empty, in
// memory of its own with room for as many elements.
template <typename T>
SlotArray<T> slotIn(UninitialisedVector<T>& shared, const SlotLayout<T>& layout, std::size_t i) {
    const std::size_t first = layout.begin(i), size = layout.begin(i + 1) - first;
    if (shared.empty()) {
        SlotArray<T> own;
        own.reserve(size);
        return own;
    }
    return SlotArray<T>(shared.data() + first, size);
}

} // namespace raylab

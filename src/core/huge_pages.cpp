#include "huge_pages.h"

#include <cstdint>
#include <new>
#include <sys/mman.h>

namespace raylab {

namespace {

// `at` rounded up to a multiple of 2 MiB (a size, or an address to start a huge page at).
std::uintptr_t roundUpToHugePage(std::uintptr_t at) {
    return (at + kHugePageBytes - 1) & ~std::uintptr_t{kHugePageBytes - 1};
}

} // namespace

void adviseHugePages(void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
    const auto begin = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t first = roundUpToHugePage(begin);
    const std::uintptr_t end = (begin + bytes) & ~(kHugePageBytes - 1);
    if (end > first) {
        ::madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE);
    }
#else
    (void)data;
    (void)bytes;
#endif
}

void* allocateHugePageArray(std::size_t bytes) {
    const std::size_t size = roundUpToHugePage(bytes);
    if (size < bytes || size + kHugePageBytes < size) {
        throw std::bad_alloc();
    }
    // Mapped one huge page larger, then trimmed to the 2 MiB boundary inside.
    void* mapped = ::mmap(nullptr, size + kHugePageBytes, PROT_READ | PROT_WRITE,
                          MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped == MAP_FAILED) {
        throw std::bad_alloc();
    }
    const auto begin = reinterpret_cast<std::uintptr_t>(mapped);
    const std::uintptr_t aligned = roundUpToHugePage(begin);
    if (aligned > begin) {
        ::munmap(mapped, aligned - begin);
    }
    const std::uintptr_t end = begin + size + kHugePageBytes;
    if (end > aligned + size) {
        ::munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
    }
    adviseHugePages(reinterpret_cast<void*>(aligned), size);
    return reinterpret_cast<void*>(aligned);
}

void freeHugePageArray(void* data, std::size_t bytes) {
    if (data) {
        ::munmap(data, roundUpToHugePage(bytes));
    }
}

} // namespace raylab

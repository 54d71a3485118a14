#pragma once
// Large buffers about to be filled at once (a mesh's triangles as they arrive from raylab-import,
// the BVH build's arrays and the wide BVH's nodes and triangle blocks) fault in 2 MiB at a time
// instead of 4 KiB where the kernel offers transparent huge pages on request (Debian's default,
// "madvise"): tens of thousands fewer page faults for a big mesh, and for a traversal reading
// blocks scattered over tens of megabytes (the dragon's are 50 MB), 512 times fewer TLB entries
// for the same bytes.

#include <cstddef>

namespace raylab {

// Advises huge pages for the whole 2 MiB pages inside [data, data + bytes); best effort (nothing
// where the system has no such advice), no effect on what the memory holds. Call before the
// memory is first touched: pages already faulted in stay small until the kernel merges them.
void adviseHugePages(void* data, std::size_t bytes);

inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

// Arrays of this size or more take huge pages of their own (uninitialised_allocator.h), those
// under 2 MiB a whole one: for 256 KiB, one fault and one 2 MiB page zeroed instead of 64 faults
// of 4 KiB, a gain where a fault is dear (10.6-11.5 us in the Zen 5 guest of PERFORMANCE.md,
// 0.22 us a 4 KiB share of a huge page: about 110 us against 700; on the Intel Xeon 1.7-1.9 us
// and 0.45-0.68 us, 230-350 us against 115), for up to 1.75 MiB of memory more than the array
// asks for. A first 1-thread Sponza build took 700 faults with 1 MiB, 37 with 256 KiB
// (PERFORMANCE.md, "Memory and page faults").
inline constexpr std::size_t kHugePageArrayBytes = std::size_t{256} << 10;

// Memory of its own for an array of `bytes` (kHugePageArrayBytes or more): mapped from the system
// on a 2 MiB boundary, rounded up to whole 2 MiB pages and advised huge pages, untouched (the
// system gives it zeroed as each page is first touched; once the last page is touched the system
// holds up to 2 MiB more than `bytes` for it, which Bvh::memoryBytes does not count, as it
// counts no allocator's overhead). Returned to the system by
// freeHugePageArray(data, bytes) with the same `bytes`, never kept for the next array. Throws
// std::bad_alloc when the system has no such memory.
void* allocateHugePageArray(std::size_t bytes);
void freeHugePageArray(void* data, std::size_t bytes);

} // namespace raylab

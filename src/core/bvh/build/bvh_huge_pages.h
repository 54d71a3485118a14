#pragma once
// Transparent huge pages for the wide BVH's arrays (internal to core). A traversal reads nodes and
// triangle blocks scattered over tens of megabytes (the dragon's blocks are 50 MB); in 4 KiB pages
// most block reads also miss the TLB, and each miss walks the page tables (twice over under
// virtualisation). Where the kernel offers huge pages on request (Linux's "madvise" mode, Debian's
// default), 2 MiB pages cover the same bytes with 512 times fewer entries.
//
// The same advice as io/huge_pages.h (core cannot include io).

#include <cstddef>

namespace raylab {

// Advises huge pages for the whole 2 MiB pages inside [data, data + bytes); best effort (nothing
// where the system has no such advice), no effect on what the memory holds. Call it before the
// memory is first touched: pages already faulted in stay small until the kernel merges them.
void adviseBvhHugePages(void* data, std::size_t bytes);

} // namespace raylab

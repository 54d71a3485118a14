#pragma once
// Large buffers about to be filled at once (a mesh's triangles as they arrive from raylab-import)
// fault in 2 MiB at a time instead of 4 KiB where the kernel offers transparent huge pages on
// request (Debian's default, "madvise"): tens of thousands fewer page faults for a big mesh.

#include <cstddef>

namespace raylab {

// Advises huge pages for the whole 2 MiB pages inside [data, data + bytes); best effort, no
// effect on what the memory holds. Call before the memory is first touched.
void adviseHugePages(void* data, std::size_t bytes);

} // namespace raylab

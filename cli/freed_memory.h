#pragma once
// How the process's allocator keeps memory it has freed (docs/performance.md, "Memory").

namespace luxgrid::cli {

// Asks glibc's malloc to keep freed memory for the next allocation instead of returning it to
// the system: blocks up to kKeptBlockBytes come from the heap (not a mapping of their own that a
// free unmaps), and a heap top is trimmed only beyond kTrimBytes. A page the process touches for
// the first time costs a fault whose zeroing, on the virtual machines luxgrid is measured on,
// takes about 11 us for 4 kB (12 MB in 34 ms, against 0.5 ms to write the same bytes again); a
// calculation that frees a patch mesh's buffers and allocates the next mesh's would pay that
// again and again. Call once, first thing in main. A no-op on other C libraries.
void keep_freed_memory();

}  // namespace luxgrid::cli

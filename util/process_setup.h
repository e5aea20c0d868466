#pragma once
// The process's set-up, done first thing in main by the program (cli/main.cpp) and by every test
// program (tests/test_main.cpp), so the tests run with the product's allocator.
//
// glibc's malloc is asked to keep the memory the process frees for its next allocations instead
// of returning it to the system: blocks up to kKeptBlockBytes come from the heap (not a mapping
// of their own that a free unmaps), and a heap top is trimmed only beyond kTrimBytes. A page the
// process touches for the first time costs a fault whose zeroing, on the virtual machines
// luxgrid is measured on, takes about 11 us for 4 kB (12 MB in 34 ms, against 0.5 ms to write the
// same bytes again); a calculation that frees a patch mesh's buffers and allocates the next
// mesh's would pay that again and again. Measured on whole runs, without it the bench hall takes
// 1.14 x the CPU time; the examples and the other bench projects are the same within the noise
// (1.01 to 1.02). A no-op on other C libraries.
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace luxgrid {

// A block this large or larger is still mapped on its own and returned at its free: the dense
// form-factor matrices and the large halls' link lists, whose pages are worth giving back.
inline constexpr int kKeptBlockBytes = 64 << 20;
// Free memory at the heap's top is given back only beyond this, and the heap grows by this
// much at a time (address space only: a page counts towards the resident size once touched).
inline constexpr int kTrimBytes = 256 << 20;
inline constexpr int kHeapGrowthBytes = 64 << 20;

// Call once, first thing in main.
inline void set_up_process() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kKeptBlockBytes);
  mallopt(M_TRIM_THRESHOLD, kTrimBytes);
  mallopt(M_TOP_PAD, kHeapGrowthBytes);
#endif
}

}  // namespace luxgrid

#include "cli/freed_memory.h"

#include <cstddef>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace luxgrid::cli {
namespace {
// A block this large or larger is still mapped on its own and returned at its free: the dense
// form-factor matrices and the large halls' link lists, whose pages are worth giving back.
constexpr int kKeptBlockBytes = 64 << 20;
// Free memory at the heap's top is given back only beyond this, and the heap grows by this
// much at a time (address space only: a page counts towards the resident size once touched).
constexpr int kTrimBytes = 256 << 20;
constexpr int kHeapGrowthBytes = 64 << 20;
}  // namespace

void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kKeptBlockBytes);
  mallopt(M_TRIM_THRESHOLD, kTrimBytes);
  mallopt(M_TOP_PAD, kHeapGrowthBytes);
#endif
}

}  // namespace luxgrid::cli

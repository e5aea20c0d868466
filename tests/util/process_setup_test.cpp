// util/process_setup.h: the test programs run with the product's allocator set-up
// (tests/test_main.cpp calls set_up_process first, as cli/main.cpp does).
#include <gtest/gtest.h>

#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "util/process_setup.h"

namespace luxgrid {
namespace {

TEST(ProcessSetup, TheTestsKeepFreedMemoryAsTheProgramDoes) {
#if defined(__GLIBC__)
  // 16 MiB is above glibc's default mapping threshold (128 KiB, rising to at most 32 MiB only
  // after such blocks were freed) and below kKeptBlockBytes: with the set-up it comes from the
  // heap, so the count of blocks mapped on their own does not change.
  static_assert(kKeptBlockBytes > (16 << 20));
  const auto mapped_before = mallinfo2().hblks;
  auto* block = static_cast<volatile char*>(std::malloc(16 << 20));
  ASSERT_NE(block, nullptr);
  block[0] = 1;
  const auto mapped_with_block = mallinfo2().hblks;
  std::free(const_cast<char*>(block));
  EXPECT_EQ(mapped_with_block, mapped_before);
#else
  GTEST_SKIP() << "the set-up is glibc's";
#endif
}

}  // namespace
}  // namespace luxgrid

// util/huge_page_allocator.h: large blocks mapped on their own and 2 MiB-aligned where the system
// offers transparent huge pages, small ones from malloc; contents kept through growth; the
// elements default-initialised (no zeroing pass).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "util/huge_page_allocator.h"

namespace luxgrid {
namespace {

TEST(HugePageAllocator, LargeBlocksAreHugePageAlignedWhereTheSystemOffersThem) {
  std::vector<double, HugePageAllocator<double>> large(kHugePageMinBytes / sizeof(double) + 1);
  const auto address = reinterpret_cast<std::uintptr_t>(large.data());
  if (huge_pages_on_request())
    EXPECT_EQ(address % kHugePageBytes, 0u);
  else
    EXPECT_EQ(address % alignof(double), 0u);
  EXPECT_TRUE(mapped_on_its_own(kHugePageMinBytes) == huge_pages_on_request());
  EXPECT_FALSE(mapped_on_its_own(kHugePageMinBytes - 1));
}

TEST(HugePageAllocator, ContentsSurviveGrowthAcrossTheThreshold) {
  // From malloc's small blocks into mapped ones and on past a huge page: every value kept.
  std::vector<std::uint32_t, HugePageAllocator<std::uint32_t>> v;
  const std::size_t n = 3 * kHugePageBytes / sizeof(std::uint32_t);
  for (std::size_t i = 0; i < n; ++i) v.push_back(static_cast<std::uint32_t>(i * 2654435761u));
  for (std::size_t i = 0; i < n; i += 4099)
    ASSERT_EQ(v[i], static_cast<std::uint32_t>(i * 2654435761u)) << i;
  v.clear();
  v.shrink_to_fit();  // released by the size it was mapped with
  EXPECT_EQ(v.capacity(), 0u);
}

TEST(HugePageAllocator, RoundsToWholeHugePages) {
  EXPECT_EQ(huge_page_rounded(1), kHugePageBytes);
  EXPECT_EQ(huge_page_rounded(kHugePageBytes), kHugePageBytes);
  EXPECT_EQ(huge_page_rounded(kHugePageBytes + 1), 2 * kHugePageBytes);
}

}  // namespace
}  // namespace luxgrid

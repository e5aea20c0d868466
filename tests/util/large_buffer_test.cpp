// util/large_buffer.h: large blocks mapped on their own and 2 MiB-aligned where the system offers
// transparent huge pages, small ones from malloc; filled buffers hold their value everywhere;
// moving hands the block over (the source left empty).
#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "util/large_buffer.h"

namespace luxgrid {
namespace {

TEST(LargeBuffer, LargeBlocksAreHugePageAlignedWhereTheSystemOffersThem) {
  const auto large = LargeBuffer<double>::uninitialised(kHugePageMinBytes / sizeof(double) + 1);
  const auto address = reinterpret_cast<std::uintptr_t>(large.data());
  if (huge_pages_on_request())
    EXPECT_EQ(address % kHugePageBytes, 0u);
  else
    EXPECT_EQ(address % alignof(double), 0u);
  EXPECT_TRUE(mapped_on_its_own(kHugePageMinBytes) == huge_pages_on_request());
  EXPECT_FALSE(mapped_on_its_own(kHugePageMinBytes - 1));
}

TEST(LargeBuffer, FilledHoldsTheValueOnBothSidesOfTheThreshold) {
  // A small block (malloc) and one past a huge page (mapped on its own): every element set.
  for (const std::size_t n : {std::size_t{1000}, 3 * kHugePageBytes / sizeof(std::uint32_t) + 7}) {
    const auto b = LargeBuffer<std::uint32_t>::filled(n, 0xA5A5A5A5u);
    ASSERT_EQ(b.size(), n);
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(b[i], 0xA5A5A5A5u) << i << " of " << n;
  }
}

TEST(LargeBuffer, MovingHandsTheBlockOver) {
  auto a = LargeBuffer<float>::filled(kHugePageMinBytes, 1.5f);
  const float* block = a.data();
  LargeBuffer<float> b = std::move(a);
  EXPECT_EQ(b.data(), block);
  EXPECT_EQ(b.size(), kHugePageMinBytes);
  EXPECT_TRUE(a.empty());  // NOLINT(bugprone-use-after-move): the moved-from state is specified
  EXPECT_EQ(a.data(), nullptr);
  b = LargeBuffer<float>::uninitialised(3);  // the large block released by its size
  EXPECT_EQ(b.size(), 3u);
  EXPECT_EQ(b.span().size(), 3u);
}

TEST(LargeBuffer, RoundsToWholeHugePages) {
  EXPECT_EQ(huge_page_rounded(1), kHugePageBytes);
  EXPECT_EQ(huge_page_rounded(kHugePageBytes), kHugePageBytes);
  EXPECT_EQ(huge_page_rounded(kHugePageBytes + 1), 2 * kHugePageBytes);
}

}  // namespace
}  // namespace luxgrid

// Arrays from the page allocator, small (operator new) and large (mapped pages).

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

#include "tailor/geometry/page_allocator.hpp"

namespace tailor {
namespace {

TEST(PageAllocator, VectorsOfEverySizeHoldTheirValues) {
  // Grown by doubling across the mapping threshold, then shrunk and freed.
  std::vector<std::int64_t, PageAllocator<std::int64_t>> values;
  for (std::int64_t i = 0; i < 300'000; ++i) values.push_back(3 * i + 1);
  for (std::int64_t i = 0; i < 300'000; ++i)
    ASSERT_EQ(values[static_cast<std::size_t>(i)], 3 * i + 1);
  values.resize(10);
  values.shrink_to_fit();
  EXPECT_EQ(std::accumulate(values.begin(), values.end(), std::int64_t{0}), 3 * 45 + 10);
}

TEST(PageAllocator, LargeArraysArePageAlignedAndZeroed) {
  PageAllocator<std::int32_t> allocator;
  const std::size_t n = PageAllocator<std::int32_t>::kMinMappedBytes / sizeof(std::int32_t) + 7;
  std::int32_t* p = allocator.allocate(n);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % 4096, 0u);
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[n - 1], 0);
  p[n - 1] = 5;
  allocator.deallocate(p, n);
  EXPECT_TRUE(allocator == PageAllocator<double>());
}

}  // namespace
}  // namespace tailor

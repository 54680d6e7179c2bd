// The cell's heap policy: buffers of a blob's size are mapped whole each time, not carved out
// of the heap once glibc has seen one freed.
#include "realtime/rt/heap_policy.hpp"

#include <gtest/gtest.h>

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cosmos {
namespace {

#if defined(__GLIBC__)
TEST(HeapPolicy, ABlobSizedBufferIsMappedEveryTimeItIsAllocated) {
  keep_heap_flat();
  constexpr std::size_t kBytes = 512 * 1024;
  for (int round = 0; round < 3; ++round) {
    const std::size_t mapped_before = mallinfo2().hblks;
    void* buffer = std::malloc(kBytes);
    ASSERT_NE(buffer, nullptr);
    asm volatile("" : : "r"(buffer) : "memory");  // kept: the compiler may elide a pair unused
    // Without the fixed threshold glibc would serve the second and third from the heap.
    EXPECT_EQ(mallinfo2().hblks, mapped_before + 1) << "round " << round;
    std::free(buffer);
    EXPECT_EQ(mallinfo2().hblks, mapped_before) << "round " << round;
  }
  return_free_heap_pages();
}
#endif

}  // namespace
}  // namespace cosmos

#include "realtime/rt/heap_policy.hpp"

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cosmos {

void keep_heap_flat() noexcept {
#if defined(__GLIBC__)
  // Buffers from 256 KiB (a range image of a small part) are mapped whole; setting the
  // thresholds also turns off glibc's raising them as large buffers are freed.
  constexpr int kMapFromBytes = 256 * 1024;
  constexpr int kTrimFromBytes = 1024 * 1024;
  mallopt(M_MMAP_THRESHOLD, kMapFromBytes);
  mallopt(M_TRIM_THRESHOLD, kTrimFromBytes);
#endif
}

void return_free_heap_pages() noexcept {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace cosmos

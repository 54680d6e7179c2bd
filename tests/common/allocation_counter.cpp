#include "tests/common/allocation_counter.hpp"

#include <cstdlib>
#include <new>

namespace cosmos::test {
namespace {

thread_local std::uint64_t allocations = 0;

void* counted_allocation(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* counted_nothrow_allocation(std::size_t size) noexcept {
  ++allocations;
  return std::malloc(size == 0 ? 1 : size);
}

void* counted_aligned_allocation(std::size_t size, std::align_val_t alignment) {
  ++allocations;
  const auto align = static_cast<std::size_t>(alignment);
  // aligned_alloc wants the size to be a multiple of the alignment.
  const std::size_t rounded = ((size == 0 ? 1 : size) + align - 1) / align * align;
  if (void* p = std::aligned_alloc(align, rounded)) return p;
  throw std::bad_alloc();
}

}  // namespace

std::uint64_t allocations_on_this_thread() noexcept { return allocations; }

}  // namespace cosmos::test

void* operator new(std::size_t size) { return cosmos::test::counted_allocation(size); }
void* operator new[](std::size_t size) { return cosmos::test::counted_allocation(size); }
void* operator new(std::size_t size, std::align_val_t alignment) {
  return cosmos::test::counted_aligned_allocation(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
  return cosmos::test::counted_aligned_allocation(size, alignment);
}
// The nothrow forms too: left to the library's, they would allocate where this file's delete
// frees (a mismatch AddressSanitizer reports).
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return cosmos::test::counted_nothrow_allocation(size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return cosmos::test::counted_nothrow_allocation(size);
}
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

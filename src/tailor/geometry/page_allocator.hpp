#pragma once
/// @file
/// An allocator that maps large arrays straight from the system, for the big buffers a
/// step fills and frees.

#include <sys/mman.h>

#include <cstddef>
#include <new>

namespace tailor {

/// Allocates arrays of at least kMinMappedBytes with mmap and frees them with munmap, so that
/// their pages go back to the system as soon as they are freed; smaller arrays come from
/// operator new. Why: glibc's malloc raises its own mapping threshold to the largest block
/// freed so far (the build's temporaries reach megabytes), after which a step's candidate
/// blocks come from the heap and their holes stay resident: the folded cloth of 90K
/// triangles peaked at 296-300 B/triangle instead of 280-282. The price: freed pages are
/// faulted in again when mapped anew (that step's traversal took about 4 % longer).
/// Stateless: all instances are equal.
template <class T>
struct PageAllocator {
  static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__);
  using value_type = T;
  static constexpr std::size_t kMinMappedBytes = std::size_t{64} << 10;

  PageAllocator() = default;
  template <class U>
  PageAllocator(const PageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kMinMappedBytes) return static_cast<T*>(::operator new(bytes));
    void* pages = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (pages == MAP_FAILED) throw std::bad_alloc();
    return static_cast<T*>(pages);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kMinMappedBytes) {
      ::operator delete(p);
    } else {
      munmap(p, bytes);
    }
  }
  template <class U>
  friend bool operator==(const PageAllocator&, const PageAllocator<U>&) noexcept {
    return true;
  }
};

}  // namespace tailor

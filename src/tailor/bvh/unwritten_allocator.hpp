#pragma once
/// @file
/// An allocator for large arrays whose every element is built right after, in parallel:
/// std::vector<T, UnwrittenAllocator<T>>::resize() leaves the new elements' storage
/// unwritten (no zeroing, no default constructor on one thread), and the owner then
/// constructs each element in place (placement new) before any use. T must be trivially
/// destructible.

#include <memory>
#include <type_traits>
#include <utility>

namespace tailor {

/// std::allocator, except that construct(p) with no argument writes nothing.
template <class T>
struct UnwrittenAllocator : std::allocator<T> {
  using std::allocator<T>::allocator;
  /// The same allocator for U.
  template <class U>
  struct rebind {
    using other = UnwrittenAllocator<U>;  ///< the rebound allocator
  };
  /// Leaves *p unwritten: its owner constructs it in place before use.
  template <class U>
  void construct(U* /*p*/) noexcept {
    static_assert(std::is_trivially_destructible_v<U>);
  }
  /// Constructs *p from `args`.
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace tailor

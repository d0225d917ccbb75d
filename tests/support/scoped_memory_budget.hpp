#pragma once
// Sets the memory budget (tailor/io/memory_budget.hpp) for one test and restores the
// previous one afterwards.

#include <cstdint>

#include "tailor/io/memory_budget.hpp"

namespace tailor::test {

class ScopedMemoryBudget {
 public:
  explicit ScopedMemoryBudget(std::uint64_t bytes) : m_previous(memory_budget()) {
    set_memory_budget(bytes);
  }
  ~ScopedMemoryBudget() { set_memory_budget(m_previous); }
  ScopedMemoryBudget(const ScopedMemoryBudget&) = delete;
  ScopedMemoryBudget& operator=(const ScopedMemoryBudget&) = delete;

 private:
  std::uint64_t m_previous;
};

}  // namespace tailor::test

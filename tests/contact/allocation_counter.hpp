#pragma once
// Counts heap allocations (replacement operator new), to check that queries allocate nothing.
// Include it in exactly ONE translation unit of a test executable (a replacement operator new is
// defined once per program).
#include <atomic>
#include <cstdlib>
#include <new>

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace sf::test {
inline std::atomic<long> g_allocations{0};
/// Heap allocations so far (operator new calls).
inline long allocation_count() {
  return g_allocations.load();
}
}  // namespace sf::test

void* operator new(std::size_t n) {
  ++sf::test::g_allocations;
  if (void* p = std::malloc(n ? n : 1)) {
    return p;
  }
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

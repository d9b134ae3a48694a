// The replacement operator new of the contact tests' program (allocation_counter.hpp): counts
// every heap allocation. Defined once per program.
#include "allocation_counter.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

namespace sf::test {
long allocation_count() {
  return g_allocations.load();
}
}  // namespace sf::test

void* operator new(std::size_t n) {
  ++g_allocations;
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

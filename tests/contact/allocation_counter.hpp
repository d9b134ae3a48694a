#pragma once
// Counts heap allocations (a replacement operator new, allocation_counter.cpp, linked once into
// the contact tests' program), to check that queries allocate nothing.

namespace sf::test {
/// Heap allocations so far (operator new calls) in this program.
long allocation_count();
}  // namespace sf::test

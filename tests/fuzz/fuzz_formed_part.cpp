// Fuzz target: the formed-part reader (read_formed_part, src/solver/formed_part.cpp, through the
// HDF5 wrapper and libhdf5), as a case with `blank.formed_part` meets it: a file another run, a
// colleague or a supplier wrote. Each input is written as formed_part.h5 and read. Checks:
// read_formed_part returns or throws sf::InputError, nothing else (no crash, no sanitizer report,
// no other exception), and what it returns is consistent (node indices within the nodes, element
// parts within the parts). The seed (tests/fuzz/seeds/formed_part, cases/verify_bounce at
// t = 1e-5 s, written by an earlier build) must be accepted.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/errors.hpp"
#include "fuzz_support.hpp"
#include "solver/formed_part.hpp"
#include "state_without_elements.hpp"

namespace {

const std::filesystem::path seed_file =
    std::filesystem::path(SF_SOURCE_DIR) / "tests/fuzz/seeds/formed_part/verify_bounce_t1e-5.h5";

// Every node index the part holds is one of its nodes (the reader's checks).
void check_consistent(const sf::FormedPart& part) {
  const auto n = part.reference_nodes.cols();
  const bool in_range =
      (part.quads.size() == 0 || (part.quads.minCoeff() >= 0 && part.quads.maxCoeff() < n)) &&
      (part.triangles.size() == 0 ||
       (part.triangles.minCoeff() >= 0 && part.triangles.maxCoeff() < n)) &&
      std::all_of(part.element_part.begin(), part.element_part.end(), [&](int p) {
        return p >= 0 && static_cast<std::size_t>(p) < part.part_names.size();
      });
  if (!in_range) {
    std::fprintf(stderr, "fuzz: read_formed_part returned a node or part index out of range\n");
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  sf::fuzz::quiet();
  try {
    check_consistent(sf::read_formed_part(seed_file));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: the seed %s does not read: %s\n", seed_file.c_str(), e.what());
    std::abort();
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = sf::fuzz::write_input("formed_part.h5", data, size);
  try {
    check_consistent(sf::read_formed_part(file));
  } catch (const sf::InputError&) {
    return 0;  // bad input, reported as such
  } catch (const std::exception& e) {
    sf::fuzz::unexpected_exception("read_formed_part", &e);
  } catch (...) {
    sf::fuzz::unexpected_exception("read_formed_part", nullptr);
  }
  return 0;
}

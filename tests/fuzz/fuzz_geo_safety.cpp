// Fuzz target: the .geo scanner that refuses commands before gmsh reads a file
// (src/meshing/geo_safety.cpp: comments, strings, Include/Merge chains). Each input is written as
// case.geo into a work folder; it is scanned only, never given to gmsh.
// Checks: check_geo_runs_no_commands returns or throws sf::InputError, nothing else.
#include <cstddef>
#include <cstdint>

#include "core/errors.hpp"
#include "fuzz_support.hpp"
#include "meshing/geo_safety.hpp"

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  sf::fuzz::quiet();
  sf::geo_system_calls_allowed() = false;
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = sf::fuzz::write_input("case.geo", data, size);
  try {
    sf::check_geo_runs_no_commands(file);
  } catch (const sf::InputError&) {
    return 0;
  } catch (const std::exception& e) {
    sf::fuzz::unexpected_exception("check_geo_runs_no_commands", &e);
  } catch (...) {
    sf::fuzz::unexpected_exception("check_geo_runs_no_commands", nullptr);
  }
  return 0;
}

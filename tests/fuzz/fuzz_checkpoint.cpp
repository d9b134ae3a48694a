// Fuzz target: the checkpoint reader (read_checkpoint, src/solver/checkpoint.cpp, through the
// HDF5 wrapper src/results/hdf5_file.cpp and libhdf5), as `sheetform run --restart` meets it. The
// state it reads into is that of a small fixed case, cases/verify_bounce (one shell over a
// floor), sized once as the case's real checkpoint in tests/fuzz/seeds/checkpoint/ says, without
// building the case's model: this target compiles the reader and the HDF5 wrapper only. Each input
// is written as checkpoint.h5 and read into a fresh copy of that state. Checks: read_checkpoint
// returns or throws sf::InputError, nothing else (no crash, no sanitizer report, no other
// exception). The seed must be accepted.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "fuzz_support.hpp"
#include "results/hdf5_file.hpp"
#include "solver/checkpoint.hpp"
#include "solver/checkpoint_fields.hpp"
#include "state_without_elements.hpp"

namespace {

const std::filesystem::path seed_file =
    std::filesystem::path(SF_SOURCE_DIR) / "tests/fuzz/seeds/checkpoint/verify_bounce_cycle60.h5";

// The case's sizes as the seed's entries give them: the tools, the contacts, each array's length.
struct Layout {
  std::size_t tools = 0;
  std::size_t contacts = 0;
  std::map<std::string, Eigen::Index> lengths;
};

const Layout& seed_layout() {
  static const Layout layout = [] {
    const sf::h5::File seed(seed_file, sf::h5::FileMode::read_only);
    Layout l;
    l.tools = seed.list("/state/tools").size();
    l.contacts = seed.list("/state/contacts").size();
    std::vector<std::string> groups = {"/state"};
    while (!groups.empty()) {  // every dataset under /state, by its name below /state/
      const std::string group = groups.back();
      groups.pop_back();
      for (const std::string& name : seed.list(group)) {
        const std::string path = group + "/" + name;
        try {
          l.lengths[path.substr(7)] = static_cast<Eigen::Index>(seed.shape(path).at(0));
        } catch (const sf::h5::Error&) {
          groups.push_back(path);  // a group
        }
      }
    }
    return l;
  }();
  return layout;
}

// Sizes every array of a state as the layout says.
class Sizer {
 public:
  explicit Sizer(const Layout& layout) : layout_(layout) {}
  template <class Scalar>
  void scalar(const std::string& /*name*/, Scalar& /*value*/) {}
  void nodes(const std::string& name, sf::Matrix3X& a) { a.resize(3, length(name) / 3); }
  void nodes(const std::string& name, sf::VectorX& a) { a.resize(length(name)); }
  void elements(const std::string& name, std::vector<double>& a, int /*n*/) {
    a.resize(static_cast<std::size_t>(length(name)));
  }

 private:
  Eigen::Index length(const std::string& name) const {
    const auto found = layout_.lengths.find(name);
    return found == layout_.lengths.end() ? 0 : found->second;
  }
  const Layout& layout_;
};

// A state of the fixed case's sizes, as `sheetform run --restart` has before it reads.
sf::SolutionState sized_state() {
  sf::SolutionState s;
  s.tools.resize(seed_layout().tools);
  s.contacts.resize(seed_layout().contacts);
  Sizer sizer(seed_layout());
  sf::visit_checkpoint_fields(sizer, s);
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  sf::fuzz::quiet();
  sf::SolutionState state = sized_state();
  try {
    sf::read_checkpoint(seed_file, state);  // the target reads a real checkpoint whole
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz: the seed %s does not read: %s\n", seed_file.c_str(), e.what());
    std::abort();
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = sf::fuzz::write_input("checkpoint.h5", data, size);
  sf::SolutionState state = sized_state();
  try {
    sf::read_checkpoint(file, state);
  } catch (const sf::InputError&) {
    return 0;  // bad input, reported as such
  } catch (const std::exception& e) {
    sf::fuzz::unexpected_exception("read_checkpoint", &e);
  } catch (...) {
    sf::fuzz::unexpected_exception("read_checkpoint", nullptr);
  }
  return 0;
}

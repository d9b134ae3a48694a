// Fuzz target: the case reader (case.toml -> CaseConfig: src/casefile/case_config*.cpp,
// toml_reader, case_overrides, unit_system). Each input is written as case.toml into a work folder
// that also holds an empty file under every mesh and table name the bundled cases use (blank.geo,
// die.msh, punch.step, ...), so that inputs mutated from a real case get past the file checks into
// the rest of the reader (read_case checks that the files exist; it does not read them). Checks:
// read_case returns or throws sf::InputError, nothing else; a case it accepts formats
// (format_resolved_case) to a resolved case that reads back, and formats again to the same text
// (but for the line naming the file it was read from).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "casefile/case_config.hpp"
#include "core/errors.hpp"
#include "fuzz_support.hpp"

namespace {

// The resolved case without its "# read from FILE" line, which names the file it was read from.
std::string without_source_line(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    end = end == std::string::npos ? text.size() : end + 1;
    if (text.compare(start, 12, "# read from ") != 0) {
      out.append(text, start, end - start);
    }
    start = end;
  }
  return out;
}

// Empty stand-ins for the files the bundled cases name (cases/*/: .geo, .msh, .step, .csv).
void make_stand_in_files() {
  namespace fs = std::filesystem;
  std::error_code error;
  for (const auto& folder : fs::directory_iterator(fs::path(SF_SOURCE_DIR) / "cases", error)) {
    if (!folder.is_directory()) {
      continue;
    }
    for (const auto& entry : fs::directory_iterator(folder.path(), error)) {
      const auto ext = entry.path().extension();
      if (entry.is_regular_file() &&
          (ext == ".geo" || ext == ".msh" || ext == ".step" || ext == ".csv")) {
        std::ofstream(sf::fuzz::work_folder() / entry.path().filename());
      }
    }
  }
  for (const char* name : {"mesh.msh", "mesh.geo", "flow.csv", "hardening.csv"}) {
    std::ofstream(sf::fuzz::work_folder() / name);
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  sf::fuzz::quiet();
  make_stand_in_files();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = sf::fuzz::write_input("case.toml", data, size);
  std::string resolved;
  try {
    resolved = sf::format_resolved_case(sf::read_case(file));
  } catch (const sf::InputError&) {
    return 0;  // bad input, reported as such
  } catch (const std::exception& e) {
    sf::fuzz::unexpected_exception("read_case", &e);
  } catch (...) {
    sf::fuzz::unexpected_exception("read_case", nullptr);
  }
  // The resolved case is a case file of its own: it reads back to the same case.
  const auto again = sf::fuzz::work_folder() / "case.resolved.toml";
  std::ofstream(again, std::ios::binary | std::ios::trunc) << resolved;
  std::string resolved_again;
  try {
    resolved_again = sf::format_resolved_case(sf::read_case(again));
  } catch (const sf::InputError& e) {
    sf::fuzz::broken("the resolved case of an accepted case does not read back",
                     std::string(e.what()) + "\n--- resolved case:\n" + resolved);
  } catch (const std::exception& e) {
    sf::fuzz::unexpected_exception("read_case (resolved case)", &e);
  } catch (...) {
    sf::fuzz::unexpected_exception("read_case (resolved case)", nullptr);
  }
  if (without_source_line(resolved_again) != without_source_line(resolved)) {
    sf::fuzz::broken("the resolved case reads back to a different case",
                     "--- first:\n" + resolved + "\n--- again:\n" + resolved_again);
  }
  return 0;
}

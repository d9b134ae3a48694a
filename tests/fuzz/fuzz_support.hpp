#pragma once
// Shared pieces of the fuzz targets (tests/fuzz): a private work folder per process, the input
// written to a file there (the readers take paths), and the rule every target checks: a reader
// given bad input throws sf::InputError and nothing else (no crash, no other exception).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>

#include "core/log.hpp"

namespace sf::fuzz {

/// A fresh folder under the temporary directory, named after the process, removed at exit.
inline const std::filesystem::path& work_folder() {
  static const std::filesystem::path folder = [] {
    const auto path = std::filesystem::temp_directory_path() /
                      ("sheetform-fuzz-" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(work_folder(), ignored);
    });
    return path;
  }();
  return folder;
}

/// Writes the fuzz input to `name` in the work folder and returns its path.
inline std::filesystem::path write_input(const std::string& name, const std::uint8_t* data,
                                         std::size_t size) {
  const auto path = work_folder() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.string().c_str());
    std::abort();
  }
  return path;
}

/// No console output from the readers (warnings would flood the fuzzer's log).
inline void quiet() {
  verbosity() = Verbosity::quiet;
  warnings_enabled() = false;
}

/// A finding: an exception other than InputError escaped a reader. Aborts, so that libFuzzer
/// (or the replay) saves the input and shows the stack.
[[noreturn]] inline void unexpected_exception(const char* where, const std::exception* e) {
  std::fprintf(stderr, "fuzz: %s threw %s: %s (a reader must throw sf::InputError only)\n", where,
               e ? typeid(*e).name() : "a non-std::exception", e ? e->what() : "");
  std::abort();
}

/// A finding: a property the target checks does not hold.
[[noreturn]] inline void broken(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz: %s\n%s\n", what, detail.c_str());
  std::abort();
}

}  // namespace sf::fuzz

#include "results/atomic_hdf5_write.hpp"

#include <fmt/core.h>

#include <system_error>

#include "core/errors.hpp"
#include "results/detached_write.hpp"

namespace sf {

void write_hdf5_atomically(const std::filesystem::path& file, const std::string& what,
                           const std::function<void(h5::File&)>& write) {
  run_detached([&] {
    std::filesystem::path temporary = file;
    temporary += ".tmp";
    try {
      h5::File out(temporary, h5::FileMode::truncate);
      write(out);
      out.close();
    } catch (const h5::Error& e) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw OutputError(fmt::format("cannot write the {} {}: {}", what, file.string(), e.what()));
    }
    std::error_code error;
    std::filesystem::rename(temporary, file, error);
    if (error) {
      throw OutputError(
          fmt::format("cannot write the {} {}: {}", what, file.string(), error.message()));
    }
  });
}

}  // namespace sf

#pragma once
// One HDF5 file written whole or not at all (a checkpoint, a formed part): written to FILE.tmp
// and renamed over FILE, in a detached child (results/detached_write.hpp), so that neither an
// error nor a kill of the run leaves a file half written or the previous one damaged.
#include <filesystem>
#include <functional>
#include <string>

#include "results/hdf5_file.hpp"

namespace sf {

/// Runs `write` on a new FILE.tmp, then renames it to `file`. Throws OutputError "cannot write
/// the `what` FILE: ..." when it cannot (the temporary file removed, an earlier `file` whole).
void write_hdf5_atomically(const std::filesystem::path& file, const std::string& what,
                           const std::function<void(h5::File&)>& write);

}  // namespace sf

#pragma once
// A damaged HDF5 file read in a child process first. libhdf5 1.10 itself uses freed memory, reads
// out of bounds or loops on some damaged files (found by fuzzing the checkpoint reader:
// tests/fuzz/regressions/checkpoint; nothing sheetform can fix in the library). So a reader of a
// file a user gives (a checkpoint) runs once in a child process, a copy of this one with its
// output silenced and a time limit: a crash or a timeout there is a damaged file, named, and this
// process never meets the damage. Then the caller reads the file itself.
#include <filesystem>
#include <functional>
#include <string>

namespace sf {

/// Runs `read` (which reads `file` through libhdf5; what it throws is ignored: the caller's own
/// read reports it again) in a child process and waits for it. Throws sf::InputError naming
/// `file` and `what` it is when the child crashes or runs past 10 s plus 1 s per 5 MB of the
/// file. When the process cannot fork, does nothing.
void read_in_child_first(const std::filesystem::path& file, const std::string& what,
                         const std::function<void()>& read);

}  // namespace sf

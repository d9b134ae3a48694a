#pragma once
// A small RAII wrapper over the HDF5 C API: one open file, objects addressed by absolute paths
// ("/parts/blank/connectivity"), write and read of double and int arrays, extendible 1-D datasets,
// scalar attributes and string datasets. Every failure throws sf::h5::Error naming the file and
// the object path, with HDF5's innermost message appended; HDF5's own automatic printing of its
// error stack is turned off. Not thread-safe (Debian's libhdf5 is built without thread safety):
// use from one thread.
#include <hdf5.h>

#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace sf::h5 {

/// An HDF5 failure; the message names the file, the object path and what HDF5 said.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Owns one HDF5 identifier (file, group, dataset, dataspace, datatype, attribute, property list)
/// and closes it with the matching H5?close function. Move-only.
class Handle {
 public:
  Handle() = default;
  /// Takes ownership of `id` (which may be invalid, i.e. negative: then nothing is closed).
  explicit Handle(hid_t id) : id_(id) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(other.release()) {}
  Handle& operator=(Handle&& other) noexcept;
  ~Handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Gives up ownership and returns the identifier.
  hid_t release() {
    hid_t id = id_;
    id_ = H5I_INVALID_HID;
    return id;
  }
  /// Closes the identifier now (errors while closing are ignored; use File::close to see them).
  void reset();

 private:
  hid_t id_ = H5I_INVALID_HID;
};

/// How File opens its file.
enum class FileMode {
  truncate,    ///< create, or empty an existing file
  read_write,  ///< open an existing file for reading and writing
  read_only,   ///< open an existing file for reading
};

/// One open HDF5 file. New files use the oldest object formats (library version bounds
/// earliest..v18), which every HDF5 >= 1.8 reads, including the one bundled with ParaView 5.11.
/// Paths are absolute HDF5 paths ("/a/b/c"); the parent groups of a written object are created
/// when missing. Closing is strong: close() closes the file for good.
class File {
 public:
  /// Opens or creates `path`; throws Error naming the path when that fails.
  File(const std::filesystem::path& path, FileMode mode);
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  File(File&&) noexcept = default;
  File& operator=(File&&) noexcept = default;
  /// Closes the file if still open, ignoring errors (call close() to see them).
  ~File() = default;

  const std::filesystem::path& path() const { return path_; }

  /// Flushes and closes the file; throws Error on failure. Later calls do nothing.
  void close();
  /// Writes everything HDF5 holds for the file to it (the operating system's cache, not yet
  /// the disk); throws Error on failure.
  void flush();

  /// True if a link `path` exists (every parent must exist too; a missing parent gives false).
  bool exists(const std::string& path) const;
  /// Creates group `path` and its missing parents; an existing group is left as it is.
  void create_group(const std::string& path);
  /// Removes the link `path` (the object's space is not reclaimed by HDF5 1.10).
  void remove(const std::string& path);
  /// Names of the links in group `path`, in increasing name order.
  std::vector<std::string> list(const std::string& path) const;

  /// Writes a new dataset of row-major shape `dims` (product must equal data.size()).
  void write(const std::string& path, std::span<const double> data,
             const std::vector<hsize_t>& dims);
  void write(const std::string& path, std::span<const int> data, const std::vector<hsize_t>& dims);
  /// Shape of dataset `path`.
  std::vector<hsize_t> shape(const std::string& path) const;
  /// Values dataset `path` holds (the product of its shape); throws Error when it is beyond what
  /// may be read into memory (a damaged file).
  std::size_t value_count(const std::string& path) const;
  /// True if dataset `path` holds 64-bit floating-point numbers.
  bool holds_doubles(const std::string& path) const;
  /// Reads a whole dataset, converted to double or int by HDF5.
  std::vector<double> read_doubles(const std::string& path) const;
  std::vector<int> read_ints(const std::string& path) const;

  /// Creates an empty 1-D double dataset of unlimited length, stored in chunks of `chunk_rows`.
  void create_extendible(const std::string& path, hsize_t chunk_rows);
  /// Writes `values` at rows [offset, offset + values.size()) of an extendible 1-D dataset and
  /// sets its length to offset + values.size() (so repeating a failed write is harmless).
  void write_rows(const std::string& path, hsize_t offset, std::span<const double> values);
  /// Appends values at the end of an extendible 1-D dataset.
  void append(const std::string& path, std::span<const double> values);

  /// Writes `text` as a scalar fixed-length string dataset (ASCII, null-padded); no size limit,
  /// unlike attributes (64 KiB in this file format).
  void write_string(const std::string& path, const std::string& text);
  std::string read_string(const std::string& path) const;

  /// True if the object at `object_path` has an attribute `name`.
  bool has_attribute(const std::string& object_path, const std::string& name) const;
  /// Scalar attributes on the object at `object_path`. An existing one of the same type is
  /// written over in place (no new space in the file); one of another type is replaced.
  void write_attribute(const std::string& object_path, const std::string& name, double value);
  void write_attribute(const std::string& object_path, const std::string& name, int value);
  void write_attribute(const std::string& object_path, const std::string& name,
                       const std::string& value);
  double read_attribute_double(const std::string& object_path, const std::string& name) const;
  int read_attribute_int(const std::string& object_path, const std::string& name) const;
  std::string read_attribute_string(const std::string& object_path, const std::string& name) const;

 private:
  /// Throws Error("<what> '<object>' in <file>: <HDF5's innermost message>").
  [[noreturn]] void fail(const std::string& what, const std::string& object) const;
  void require_open(const std::string& object) const;
  void write_array(const std::string& path, const void* data, std::size_t count, hid_t mem_type,
                   hid_t file_type, const std::vector<hsize_t>& dims);
  void read_array(const std::string& path, void* data, std::size_t count, hid_t mem_type) const;
  Handle open_object(const std::string& path) const;
  void write_attribute_raw(const std::string& object_path, const std::string& name, hid_t file_type,
                           hid_t mem_type, const void* value);
  void read_attribute_raw(const std::string& object_path, const std::string& name, hid_t mem_type,
                          void* value) const;

  std::filesystem::path path_;
  Handle file_;
};

}  // namespace sf::h5

#include "results/hdf5_file.hpp"

#include <algorithm>
#include <functional>
#include <mutex>
#include <numeric>

namespace sf::h5 {
namespace {

// HDF5 1.10 closes the files still open when the process exits, and crashes (a segmentation
// fault in H5F__close_cb) on a file whose close failed, as after a full disk. Every file here is
// closed by its owner, so the library's exit handler has nothing to do: turn it off, before the
// first HDF5 call (static initialisation; later calls are ignored by HDF5).
[[maybe_unused]] const herr_t no_exit_handler = H5dont_atexit();

/// Turns off HDF5's automatic printing of its error stack (we report errors as exceptions).
void initialize_library() {
  static std::once_flag once;
  std::call_once(once, [] {
    H5open();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  });
}

/// The most specific message on HDF5's current error stack (then clears the stack).
std::string take_hdf5_message() {
  std::string message;
  auto first_description = [](unsigned n, const H5E_error2_t* error, void* out) -> herr_t {
    auto* text = static_cast<std::string*>(out);
    if (n == 0 && error->desc != nullptr) {
      *text = error->desc;
    }
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, first_description, &message);
  H5Eclear2(H5E_DEFAULT);
  return message.empty() ? "no message from HDF5" : message;
}

hsize_t product(const std::vector<hsize_t>& dims) {
  return std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
}

std::string dims_text(const std::vector<hsize_t>& dims) {
  std::string text = "[";
  for (std::size_t i = 0; i < dims.size(); ++i) {
    text += (i ? "][" : "") + std::to_string(dims[i]);
  }
  return text + "]";
}

/// Values a dataspace holds (-1 when HDF5 cannot tell): a scalar read must meet exactly 1, or
/// HDF5 would write past the one value it is given.
hssize_t point_count(hid_t space) {
  return space < 0 ? -1 : H5Sget_simple_extent_npoints(space);
}

/// The longest text read from a file: more is a damaged file, not text (attributes of this format
/// hold 64 KiB at most; run information is a resolved case).
constexpr std::size_t max_text_bytes = std::size_t{1} << 28;

/// The most values read into memory at once (16 GiB of doubles): a damaged file's shape may claim
/// any number.
constexpr hsize_t max_values = hsize_t{1} << 31;

/// Writes over attribute `name` of `object` in place when it has type `file_type`: the write then
/// changes one block of the file (the results' frame count, their commit record, relies on it).
/// False (nothing written) when its type differs.
bool overwrite_attribute(hid_t object, const std::string& name, hid_t file_type, hid_t mem_type,
                         const void* value) {
  Handle attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT));
  Handle type(attribute.valid() ? H5Aget_type(attribute.get()) : H5I_INVALID_HID);
  if (!type.valid() || H5Tequal(type.get(), file_type) <= 0) {
    return false;
  }
  return H5Awrite(attribute.get(), mem_type, value) >= 0;
}

/// A fixed-length UTF-8 string type of `size` bytes (at least 1), null-padded.
Handle make_string_type(std::size_t size) {
  Handle type(H5Tcopy(H5T_C_S1));
  if (!type.valid() || H5Tset_size(type.get(), std::max<std::size_t>(size, 1)) < 0 ||
      H5Tset_strpad(type.get(), H5T_STR_NULLPAD) < 0 ||
      H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0) {
    return Handle();
  }
  return type;
}

std::string strip_padding(std::string text) {
  text.erase(std::find(text.begin(), text.end(), '\0'), text.end());
  return text;
}

}  // namespace

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.release();
  }
  return *this;
}

void Handle::reset() {
  if (id_ < 0) {
    return;
  }
  switch (H5Iget_type(id_)) {
    case H5I_FILE:
      H5Fclose(id_);
      break;
    case H5I_GROUP:
      H5Gclose(id_);
      break;
    case H5I_DATASET:
      H5Dclose(id_);
      break;
    case H5I_DATASPACE:
      H5Sclose(id_);
      break;
    case H5I_DATATYPE:
      H5Tclose(id_);
      break;
    case H5I_ATTR:
      H5Aclose(id_);
      break;
    case H5I_GENPROP_LST:
      H5Pclose(id_);
      break;
    default:
      H5Idec_ref(id_);
      break;
  }
  id_ = H5I_INVALID_HID;
}

File::File(const std::filesystem::path& path, FileMode mode) : path_(path) {
  initialize_library();
  Handle access(H5Pcreate(H5P_FILE_ACCESS));
  if (!access.valid() ||
      H5Pset_libver_bounds(access.get(), H5F_LIBVER_EARLIEST, H5F_LIBVER_V18) < 0 ||
      H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG) < 0) {
    fail("cannot set up file access for", "/");
  }
  const std::string name = path.string();
  switch (mode) {
    case FileMode::truncate:
      file_ = Handle(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()));
      break;
    case FileMode::read_write:
      file_ = Handle(H5Fopen(name.c_str(), H5F_ACC_RDWR, access.get()));
      break;
    case FileMode::read_only:
      file_ = Handle(H5Fopen(name.c_str(), H5F_ACC_RDONLY, access.get()));
      break;
  }
  if (!file_.valid()) {
    throw Error("cannot " + std::string(mode == FileMode::truncate ? "create" : "open") +
                " HDF5 file '" + name + "': " + take_hdf5_message());
  }
}

void File::close() {
  if (!file_.valid()) {
    return;
  }
  if (H5Fclose(file_.release()) < 0) {
    throw Error("cannot close HDF5 file '" + path_.string() + "': " + take_hdf5_message());
  }
}

void File::flush() {
  require_open("/");
  if (H5Fflush(file_.get(), H5F_SCOPE_LOCAL) < 0) {
    throw Error("cannot flush HDF5 file '" + path_.string() + "': " + take_hdf5_message());
  }
}

void File::fail(const std::string& what, const std::string& object) const {
  throw Error(what + " '" + object + "' in HDF5 file '" + path_.string() +
              "': " + take_hdf5_message());
}

void File::require_open(const std::string& object) const {
  if (!file_.valid()) {
    throw Error("HDF5 file '" + path_.string() + "' is closed (accessing '" + object + "')");
  }
}

bool File::exists(const std::string& path) const {
  require_open(path);
  if (path == "/") {
    return true;
  }
  // H5Lexists fails (rather than answering false) when an intermediate group is missing, so
  // check each prefix in turn.
  std::size_t end = 0;
  while (end != std::string::npos) {
    end = path.find('/', end + 1);
    const std::string prefix = path.substr(0, end);
    const htri_t found = H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT);
    if (found < 0) {
      fail("cannot look up", prefix);
    }
    if (found == 0) {
      return false;
    }
  }
  return true;
}

void File::create_group(const std::string& path) {
  require_open(path);
  if (exists(path)) {
    return;
  }
  Handle links(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_create_intermediate_group(links.get(), 1);
  Handle group(H5Gcreate2(file_.get(), path.c_str(), links.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!group.valid()) {
    fail("cannot create group", path);
  }
}

void File::remove(const std::string& path) {
  require_open(path);
  if (H5Ldelete(file_.get(), path.c_str(), H5P_DEFAULT) < 0) {
    fail("cannot remove", path);
  }
}

std::vector<std::string> File::list(const std::string& path) const {
  require_open(path);
  Handle group(H5Gopen2(file_.get(), path.c_str(), H5P_DEFAULT));
  H5G_info_t info;
  if (!group.valid() || H5Gget_info(group.get(), &info) < 0) {
    fail("cannot open group", path);
  }
  std::vector<std::string> names;
  names.reserve(info.nlinks);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t size = H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                            nullptr, 0, H5P_DEFAULT);
    if (size < 0) {
      fail("cannot list group", path);
    }
    std::string name(static_cast<std::size_t>(size) + 1, '\0');
    H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(size));
    names.push_back(std::move(name));
  }
  return names;
}

void File::write_array(const std::string& path, const void* data, std::size_t count, hid_t mem_type,
                       hid_t file_type, const std::vector<hsize_t>& dims) {
  require_open(path);
  if (product(dims) != count) {
    throw Error("cannot write '" + path + "' in HDF5 file '" + path_.string() + "': shape " +
                dims_text(dims) + " does not hold " + std::to_string(count) + " values");
  }
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  Handle links(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_create_intermediate_group(links.get(), 1);
  Handle dataset(H5Dcreate2(file_.get(), path.c_str(), file_type, space.get(), links.get(),
                            H5P_DEFAULT, H5P_DEFAULT));
  if (!dataset.valid()) {
    fail("cannot create dataset", path);
  }
  if (count > 0 && H5Dwrite(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
    fail("cannot write dataset", path);
  }
}

void File::write(const std::string& path, std::span<const double> data,
                 const std::vector<hsize_t>& dims) {
  write_array(path, data.data(), data.size(), H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, dims);
}

void File::write(const std::string& path, std::span<const int> data,
                 const std::vector<hsize_t>& dims) {
  static_assert(sizeof(int) == 4, "connectivity is stored as 32-bit integers");
  write_array(path, data.data(), data.size(), H5T_NATIVE_INT, H5T_STD_I32LE, dims);
}

std::vector<hsize_t> File::shape(const std::string& path) const {
  require_open(path);
  Handle dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT));
  if (!dataset.valid()) {
    fail("cannot open dataset", path);
  }
  Handle space(H5Dget_space(dataset.get()));
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) {
    fail("cannot read the shape of", path);
  }
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

void File::read_array(const std::string& path, void* data, std::size_t count,
                      hid_t mem_type) const {
  Handle dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT));
  if (!dataset.valid()) {
    fail("cannot open dataset", path);
  }
  if (count > 0 && H5Dread(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0) {
    fail("cannot read dataset", path);
  }
}

bool File::holds_doubles(const std::string& path) const {
  require_open(path);
  Handle dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT));
  if (!dataset.valid()) {
    fail("cannot open dataset", path);
  }
  Handle type(H5Dget_type(dataset.get()));
  return type.valid() && H5Tget_class(type.get()) == H5T_FLOAT && H5Tget_size(type.get()) == 8;
}

std::size_t File::value_count(const std::string& path) const {
  hsize_t count = 1;
  for (const hsize_t n : shape(path)) {
    if (n != 0 && count > max_values / n) {
      throw Error("cannot read '" + path + "' in HDF5 file '" + path_.string() + "': shape " +
                  dims_text(shape(path)) + " is too large");
    }
    count *= n;
  }
  return static_cast<std::size_t>(count);
}

std::vector<double> File::read_doubles(const std::string& path) const {
  std::vector<double> values(value_count(path));
  read_array(path, values.data(), values.size(), H5T_NATIVE_DOUBLE);
  return values;
}

std::vector<int> File::read_ints(const std::string& path) const {
  std::vector<int> values(value_count(path));
  read_array(path, values.data(), values.size(), H5T_NATIVE_INT);
  return values;
}

void File::create_extendible(const std::string& path, hsize_t chunk_rows) {
  require_open(path);
  const hsize_t initial = 0;
  const hsize_t unlimited = H5S_UNLIMITED;
  chunk_rows = std::max<hsize_t>(chunk_rows, 1);
  Handle space(H5Screate_simple(1, &initial, &unlimited));
  Handle layout(H5Pcreate(H5P_DATASET_CREATE));
  Handle links(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_create_intermediate_group(links.get(), 1);
  if (H5Pset_chunk(layout.get(), 1, &chunk_rows) < 0) {
    fail("cannot set chunks of", path);
  }
  Handle dataset(H5Dcreate2(file_.get(), path.c_str(), H5T_IEEE_F64LE, space.get(), links.get(),
                            layout.get(), H5P_DEFAULT));
  if (!dataset.valid()) {
    fail("cannot create dataset", path);
  }
}

void File::append(const std::string& path, std::span<const double> values) {
  const std::vector<hsize_t> dims = shape(path);
  if (dims.size() != 1) {
    throw Error("cannot append to '" + path + "' in HDF5 file '" + path_.string() +
                "': it is not 1-D");
  }
  write_rows(path, dims[0], values);
}

void File::write_rows(const std::string& path, hsize_t offset, std::span<const double> values) {
  require_open(path);
  Handle dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT));
  if (!dataset.valid()) {
    fail("cannot open dataset", path);
  }
  const hsize_t count = values.size();
  const hsize_t new_size = offset + count;
  if (H5Dset_extent(dataset.get(), &new_size) < 0) {
    fail("cannot resize dataset", path);
  }
  if (count == 0) {
    return;
  }
  Handle file_space(H5Dget_space(dataset.get()));
  Handle memory_space(H5Screate_simple(1, &count, nullptr));
  if (H5Sget_simple_extent_ndims(file_space.get()) != 1 ||
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &offset, nullptr, &count, nullptr) <
          0 ||
      H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), H5P_DEFAULT,
               values.data()) < 0) {
    fail("cannot write rows of dataset", path);
  }
}

void File::write_string(const std::string& path, const std::string& text) {
  require_open(path);
  Handle type = make_string_type(text.size());
  Handle space(H5Screate(H5S_SCALAR));
  Handle links(H5Pcreate(H5P_LINK_CREATE));
  H5Pset_create_intermediate_group(links.get(), 1);
  Handle dataset(H5Dcreate2(file_.get(), path.c_str(), type.get(), space.get(), links.get(),
                            H5P_DEFAULT, H5P_DEFAULT));
  if (!dataset.valid()) {
    fail("cannot create string dataset", path);
  }
  std::string padded = text;
  padded.resize(std::max<std::size_t>(text.size(), 1), '\0');
  if (H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, padded.data()) < 0) {
    fail("cannot write string dataset", path);
  }
}

std::string File::read_string(const std::string& path) const {
  require_open(path);
  Handle dataset(H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT));
  if (!dataset.valid()) {
    fail("cannot open dataset", path);
  }
  Handle file_type(H5Dget_type(dataset.get()));
  Handle space(H5Dget_space(dataset.get()));
  if (H5Tget_class(file_type.get()) != H5T_STRING || H5Tis_variable_str(file_type.get()) != 0 ||
      point_count(space.get()) != 1 || H5Tget_size(file_type.get()) > max_text_bytes) {
    throw Error("cannot read '" + path + "' in HDF5 file '" + path_.string() +
                "': not one fixed-length string");
  }
  const std::size_t size = H5Tget_size(file_type.get());
  Handle type = make_string_type(size);
  std::string text(size, '\0');
  if (H5Dread(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0) {
    fail("cannot read string dataset", path);
  }
  return strip_padding(std::move(text));
}

Handle File::open_object(const std::string& path) const {
  require_open(path);
  Handle object(H5Oopen(file_.get(), path.c_str(), H5P_DEFAULT));
  if (!object.valid()) {
    fail("cannot open object", path);
  }
  return object;
}

bool File::has_attribute(const std::string& object_path, const std::string& name) const {
  Handle object = open_object(object_path);
  const htri_t found = H5Aexists(object.get(), name.c_str());
  if (found < 0) {
    fail("cannot look up attribute", object_path + "@" + name);
  }
  return found > 0;
}

void File::write_attribute_raw(const std::string& object_path, const std::string& name,
                               hid_t file_type, hid_t mem_type, const void* value) {
  Handle object = open_object(object_path);
  const std::string where = object_path + "@" + name;
  const htri_t found = H5Aexists(object.get(), name.c_str());
  if (found > 0 && overwrite_attribute(object.get(), name, file_type, mem_type, value)) {
    return;
  }
  if (found < 0 || (found > 0 && H5Adelete(object.get(), name.c_str()) < 0)) {
    fail("cannot replace attribute", where);
  }
  Handle space(H5Screate(H5S_SCALAR));
  Handle attribute(
      H5Acreate2(object.get(), name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attribute.valid() || H5Awrite(attribute.get(), mem_type, value) < 0) {
    fail("cannot write attribute", where);
  }
}

void File::read_attribute_raw(const std::string& object_path, const std::string& name,
                              hid_t mem_type, void* value) const {
  Handle object = open_object(object_path);
  Handle attribute(H5Aopen(object.get(), name.c_str(), H5P_DEFAULT));
  if (!attribute.valid()) {
    fail("cannot read attribute", object_path + "@" + name);
  }
  Handle space(H5Aget_space(attribute.get()));
  if (point_count(space.get()) != 1) {
    throw Error("cannot read attribute '" + object_path + "@" + name + "' in HDF5 file '" +
                path_.string() + "': not a single value");
  }
  if (H5Aread(attribute.get(), mem_type, value) < 0) {
    fail("cannot read attribute", object_path + "@" + name);
  }
}

void File::write_attribute(const std::string& object_path, const std::string& name, double value) {
  write_attribute_raw(object_path, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void File::write_attribute(const std::string& object_path, const std::string& name, int value) {
  write_attribute_raw(object_path, name, H5T_STD_I32LE, H5T_NATIVE_INT, &value);
}

void File::write_attribute(const std::string& object_path, const std::string& name,
                           const std::string& value) {
  Handle type = make_string_type(value.size());
  std::string padded = value;
  padded.resize(std::max<std::size_t>(value.size(), 1), '\0');
  write_attribute_raw(object_path, name, type.get(), type.get(), padded.data());
}

double File::read_attribute_double(const std::string& object_path, const std::string& name) const {
  double value = 0.0;
  read_attribute_raw(object_path, name, H5T_NATIVE_DOUBLE, &value);
  return value;
}

int File::read_attribute_int(const std::string& object_path, const std::string& name) const {
  int value = 0;
  read_attribute_raw(object_path, name, H5T_NATIVE_INT, &value);
  return value;
}

std::string File::read_attribute_string(const std::string& object_path,
                                        const std::string& name) const {
  Handle object = open_object(object_path);
  const std::string where = object_path + "@" + name;
  Handle attribute(H5Aopen(object.get(), name.c_str(), H5P_DEFAULT));
  if (!attribute.valid()) {
    fail("cannot open attribute", where);
  }
  Handle file_type(H5Aget_type(attribute.get()));
  Handle space(H5Aget_space(attribute.get()));
  if (H5Tget_class(file_type.get()) != H5T_STRING || H5Tis_variable_str(file_type.get()) != 0 ||
      point_count(space.get()) != 1 || H5Tget_size(file_type.get()) > max_text_bytes) {
    throw Error("cannot read attribute '" + where + "' in HDF5 file '" + path_.string() +
                "': not one fixed-length string");
  }
  const std::size_t size = H5Tget_size(file_type.get());
  Handle type = make_string_type(size);
  std::string text(size, '\0');
  if (H5Aread(attribute.get(), type.get(), text.data()) < 0) {
    fail("cannot read attribute", where);
  }
  return strip_padding(std::move(text));
}

}  // namespace sf::h5

#include "solver/checkpoint.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "results/atomic_hdf5_write.hpp"
#include "results/hdf5_file.hpp"
#include "results/hdf5_probe.hpp"
#include "solver/checkpoint_fields.hpp"

namespace sf {

namespace {

constexpr const char* kFormat = "sheetform checkpoint";
// 2: the operation and the tools' motion origins; 3: turns; 4: the contact's normal forces and
// sliding distances
constexpr int kFormatVersion = 5;

std::span<const double> values(const double* data, Eigen::Index size) {
  return {data, static_cast<std::size_t>(size)};
}

// Writes every field as a dataset under /state: scalars as one value (integers are exact in a
// double below 2^53), arrays flat, in their memory order.
class FieldWriter {
 public:
  explicit FieldWriter(h5::File& file) : file_(file) {}
  void scalar(const std::string& name, double value) { write(name, values(&value, 1)); }
  void scalar(const std::string& name, long value) { scalar(name, static_cast<double>(value)); }
  void scalar(const std::string& name, int value) { scalar(name, static_cast<double>(value)); }
  void scalar(const std::string& name, bool value) { scalar(name, value ? 1.0 : 0.0); }
  void nodes(const std::string& name, const Matrix3X& a) {
    write(name, values(a.data(), a.size()));
  }
  void nodes(const std::string& name, const VectorX& a) { write(name, values(a.data(), a.size())); }
  void elements(const std::string& name, const std::vector<double>& a, int /*n*/) {
    write(name, a);
  }

 private:
  void write(const std::string& name, std::span<const double> data) {
    file_.write("/state/" + name, data, {data.size()});
  }
  h5::File& file_;
};

// `value` as an Integer, or an InputError naming `what` when it is not a whole number in range
// (a cast of anything else would be undefined or silently wrong).
template <class Integer>
Integer checked_whole(double value, const std::string& where, const std::string& what,
                      double lowest = static_cast<double>(std::numeric_limits<Integer>::min())) {
  const double beyond = std::ldexp(1.0, std::numeric_limits<Integer>::digits);  // exact
  if (!(value >= lowest && value < beyond && value == std::trunc(value))) {
    throw InputError(
        fmt::format("{}: {} is {}, not a whole number from {} to {} (a damaged checkpoint)", where,
                    what, value, lowest, beyond - 1.0));
  }
  return static_cast<Integer>(value);
}

// Reads every field back into a state of the model's sizes; a size that differs is the
// checkpoint of another model.
class FieldReader {
 public:
  FieldReader(const h5::File& file, std::string where) : file_(file), where_(std::move(where)) {}
  void scalar(const std::string& name, double& value) { value = read(name, 1).front(); }
  void scalar(const std::string& name, long& value) { value = whole<long>(name); }
  void scalar(const std::string& name, int& value) { value = whole<int>(name); }
  void scalar(const std::string& name, bool& value) { value = whole<int>(name) != 0; }
  void nodes(const std::string& name, Matrix3X& a) { copy(name, a.data(), a.size()); }
  void nodes(const std::string& name, VectorX& a) { copy(name, a.data(), a.size()); }
  void elements(const std::string& name, std::vector<double>& a, int /*n*/) {
    copy(name, a.data(), static_cast<Eigen::Index>(a.size()));
  }

 private:
  // The entry as the writer stores it (a 1-D array of doubles of the model's size), checked
  // before anything is read: a damaged or foreign file gets its entry named.
  std::vector<double> read(const std::string& name, std::size_t expected) {
    const std::string path = "/state/" + name;
    if (!file_.exists(path)) {
      throw InputError(
          fmt::format("{}: no entry {} (a checkpoint of another version?)", where_, path));
    }
    if (!file_.holds_doubles(path)) {
      throw InputError(fmt::format(
          "{}: entry {} does not hold 64-bit floating-point numbers (a damaged checkpoint)", where_,
          path));
    }
    const std::vector<hsize_t> shape = file_.shape(path);
    if (shape.size() != 1) {
      throw InputError(
          fmt::format("{}: entry {} is an array of {} dimensions, a checkpoint "
                      "stores a list (a damaged checkpoint)",
                      where_, path, shape.size()));
    }
    if (shape[0] != expected) {
      throw InputError(fmt::format(
          "{}: entry {} holds {} values, the case's model needs {} (a checkpoint of another "
          "mesh or case)",
          where_, path, shape[0], expected));
    }
    return file_.read_doubles(path);
  }
  template <class Integer>
  Integer whole(const std::string& name) {
    return checked_whole<Integer>(read(name, 1).front(), where_, "entry /state/" + name);
  }
  void copy(const std::string& name, double* target, Eigen::Index size) {
    const std::vector<double> data = read(name, static_cast<std::size_t>(size));
    std::copy(data.begin(), data.end(), target);
  }
  const h5::File& file_;
  std::string where_;
};

void write_info(h5::File& file, const CheckpointInfo& info) {
  file.write_attribute("/", "format", std::string(kFormat));
  file.write_attribute("/", "format_version", kFormatVersion);
  file.write_attribute("/", "case_digest", info.case_digest);
  file.write_attribute("/", "git_hash", info.git_hash);
  file.write_attribute("/", "end_time", info.end_time);
  file.create_group("/loop");
  file.write_attribute("/loop", "dt_previous", info.loop.dt_previous);
  file.write_attribute("/loop", "last_frame_time", info.loop.last_frame_time);
  file.write_attribute("/loop", "warned_added_mass", info.loop.warned_added_mass ? 1 : 0);
  const OutputMark& o = info.output;
  file.create_group("/output");
  file.write_attribute("/output", "frames", o.frames);
  file.write_attribute("/output", "history_rows", static_cast<double>(o.history_rows));
  file.write_attribute("/output", "last_history_cycle", static_cast<double>(o.last_history_cycle));
  file.write_attribute("/output", "run_id", o.run_id);
  file.write_attribute("/output", "last_audit_cycle", static_cast<double>(o.last_audit_cycle));
  file.write_attribute("/output", "audits", static_cast<int>(o.audits.size()));
  for (std::size_t a = 0; a < o.audits.size(); ++a) {
    const SearchAuditRecord& r = o.audits[a];
    const std::vector<double> counts = {static_cast<double>(r.last.nodes_checked),
                                        static_cast<double>(r.last.misses),
                                        r.last.max_gap_error,
                                        static_cast<double>(r.audits),
                                        static_cast<double>(r.max_misses),
                                        r.max_misses_time,
                                        static_cast<double>(r.total_misses),
                                        r.max_gap_error};
    file.write("/output/audit" + std::to_string(a), counts, {counts.size()});
  }
}

// A count kept as a double attribute: a whole number, not negative.
template <class Integer>
Integer read_count(const h5::File& file, const std::string& object, const std::string& name,
                   const std::string& where, double lowest = 0.0) {
  return checked_whole<Integer>(file.read_attribute_double(object, name), where,
                                fmt::format("{}@{}", object, name), lowest);
}

SearchAuditRecord read_audit(const h5::File& file, const std::string& where, int a) {
  const std::string path = "/output/audit" + std::to_string(a);
  if (!file.holds_doubles(path) || file.shape(path) != std::vector<hsize_t>{8}) {
    throw InputError(where + ": " + path + " is damaged (8 numbers expected)");
  }
  const std::vector<double> c = file.read_doubles(path);
  const std::string what = path + " value ";
  SearchAuditRecord r;
  r.last.nodes_checked = checked_whole<int>(c[0], where, what + "0", 0.0);
  r.last.misses = checked_whole<int>(c[1], where, what + "1", 0.0);
  r.last.max_gap_error = c[2];
  r.audits = checked_whole<int>(c[3], where, what + "3", 0.0);
  r.max_misses = checked_whole<int>(c[4], where, what + "4", 0.0);
  r.max_misses_time = c[5];
  r.total_misses = checked_whole<long>(c[6], where, what + "6", 0.0);
  r.max_gap_error = c[7];
  return r;
}

// A name the writer made (a digest, a build's hash, a run id): letters, digits, '-' only. A
// damaged file's bytes are refused here rather than printed in a later message.
std::string read_name(const h5::File& file, const std::string& object, const std::string& name,
                      const std::string& where) {
  std::string text = file.read_attribute_string(object, name);
  const bool plain = !text.empty() && text.size() <= 64 &&
                     std::all_of(text.begin(), text.end(),
                                 [](unsigned char c) { return std::isalnum(c) != 0 || c == '-'; });
  if (!plain) {
    throw InputError(fmt::format("{}: {}@{} is not a name sheetform writes (a damaged checkpoint)",
                                 where, object, name));
  }
  return text;
}

CheckpointInfo read_info(const h5::File& file, const std::string& where) {
  CheckpointInfo info;
  info.case_digest = read_name(file, "/", "case_digest", where);
  info.git_hash = read_name(file, "/", "git_hash", where);
  info.end_time = file.read_attribute_double("/", "end_time");
  info.loop.dt_previous = file.read_attribute_double("/loop", "dt_previous");
  info.loop.last_frame_time = file.read_attribute_double("/loop", "last_frame_time");
  info.loop.warned_added_mass = file.read_attribute_int("/loop", "warned_added_mass") != 0;
  OutputMark& o = info.output;
  o.frames = file.read_attribute_int("/output", "frames");
  if (o.frames < 0) {
    throw InputError(
        fmt::format("{}: /output@frames is {} (a damaged checkpoint)", where, o.frames));
  }
  o.history_rows = read_count<std::size_t>(file, "/output", "history_rows", where);
  o.last_history_cycle = read_count<long>(file, "/output", "last_history_cycle", where, -1.0);
  o.run_id = read_name(file, "/output", "run_id", where);
  o.last_audit_cycle = read_count<long>(file, "/output", "last_audit_cycle", where, -1.0);
  const int audits = file.read_attribute_int("/output", "audits");
  for (int a = 0; a < audits; ++a) {  // a damaged count meets a missing entry soon
    o.audits.push_back(read_audit(file, where, a));
  }
  return info;
}

// The reading itself, once libhdf5 is known to survive the file.
CheckpointInfo read_checked_checkpoint(const std::filesystem::path& file, SolutionState& state) {
  const std::string where = file.string();
  try {
    const h5::File in(file, h5::FileMode::read_only);
    if (!in.exists("/state") || in.read_attribute_string("/", "format") != kFormat) {
      throw InputError(where + ": not a sheetform checkpoint");
    }
    const int version = in.read_attribute_int("/", "format_version");
    if (version != kFormatVersion) {
      throw InputError(fmt::format("{}: checkpoint format {}, this build reads format {}", where,
                                   version, kFormatVersion));
    }
    CheckpointInfo info = read_info(in, where);
    FieldReader reader(in, where);
    visit_checkpoint_fields(reader, state);
    if (!(std::isfinite(state.time) && state.time >= 0.0 && std::isfinite(state.dt) &&
          state.dt >= 0.0)) {
      throw InputError(
          fmt::format("{}: entry /state/time or /state/dt is {} or {}, not a time "
                      "(a damaged checkpoint)",
                      where, state.time, state.dt));
    }
    return info;
  } catch (const h5::Error& e) {
    throw InputError(where + ": cannot read the checkpoint: " + e.what());
  }
}

}  // namespace

void write_checkpoint(const std::filesystem::path& file, const SolutionState& state,
                      const CheckpointInfo& info) {
  // In a detached child: a kill of the run cannot leave the temporary file behind, the child
  // finishes and renames it (results/atomic_hdf5_write.hpp).
  write_hdf5_atomically(file, "checkpoint", [&](h5::File& out) {
    write_info(out, info);
    FieldWriter writer(out);
    visit_checkpoint_fields(writer, state);
  });
}

CheckpointInfo read_checkpoint(const std::filesystem::path& file, SolutionState& state) {
  const std::string where = file.string();
  if (!std::filesystem::is_regular_file(file)) {
    throw InputError(where + ": no such checkpoint file (a run writes <results>/checkpoint.h5)");
  }
  // libhdf5 may crash on a damaged file: once in a child first (results/hdf5_probe.hpp).
  read_in_child_first(file, "checkpoint", [&] { read_checked_checkpoint(file, state); });
  return read_checked_checkpoint(file, state);
}

}  // namespace sf

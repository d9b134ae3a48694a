#include "results/results_writer.hpp"

#include <fmt/core.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <stdexcept>
#include <system_error>

#include "core/comma_list.hpp"
#include "core/errors.hpp"
#include "core/log.hpp"
#include "core/result_name.hpp"
#include "results/detached_write.hpp"
#include "results/hdf5_file.hpp"

namespace sf {
namespace {

constexpr const char* results_file_name = "results.h5";
constexpr int format_version = 1;
constexpr hsize_t history_chunk_rows = 1024;
// The commit record: /parts attribute "frames", the number of frames written whole. A frame
// group at or past it is a write that was cut (only a kill of every process of the run at once
// or a power loss can cut one); readers ignore it and the next write replaces it.
constexpr const char* frames_attribute = "frames";

void check_name(const std::string& name, const std::string& what) {
  if (!is_plain_name(name)) {
    throw std::invalid_argument(what + " '" + name + "' is not a valid name (" +
                                std::string(kPlainNameRule) + ")");
  }
}

std::string part_path(const std::string& part) {
  return "/parts/" + part;
}

// Where the part's mesh after its `index`-th change (a trim) is kept; the first mesh is the
// part's own group.
std::string topology_path(const std::string& part, int index) {
  return part_path(part) + "/topologies/" + std::to_string(index);
}

// The grid of a mesh stored at `path` (as write_topology wrote it).
XdmfPart stored_grid(const h5::File& file, const std::string& name, const std::string& path) {
  XdmfPart grid;
  grid.name = name;
  grid.nodes_per_cell = file.read_attribute_int(path, "nodes_per_cell");
  grid.node_count = file.shape(path + "/reference_coordinates").at(0);
  grid.cell_count = file.shape(path + "/connectivity").at(0);
  grid.connectivity_dataset = path + "/connectivity";
  if (grid.nodes_per_cell == 0) {
    grid.nodes_per_cell = 4;
    grid.cell_count += file.shape(path + "/triangle_connectivity").at(0);
    grid.connectivity_dataset = path + "/mixed_connectivity";
    grid.mixed_connectivity_size = file.shape(grid.connectivity_dataset).at(0);
  }
  return grid;
}

std::string frame_path(const std::string& part, int index) {
  return part_path(part) + "/frames/" + frame_group_name(index);
}

hsize_t to_hsize(Eigen::Index n) {
  return static_cast<hsize_t>(n);
}

// Runs a write to the results; a failure of the system (a full disk, a folder gone) becomes an
// OutputError, which the command reports with its own exit code.
template <class Write>
void writing(const std::filesystem::path& directory, Write write) {
  try {
    write();
  } catch (const InputError&) {
    throw;
  } catch (const OutputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (what.find("No space left on device") != std::string::npos ||
        what.find("errno = 28") != std::string::npos) {
      throw OutputError("cannot write the results in " + directory.string() +
                        ": the disk is full (No space left on device)");
    }
    throw OutputError("cannot write the results: " + what);
  }
}

// Bytes the process may still add to `file` in `directory`: the file system's free space for
// unprivileged users and the file-size limit (ulimit -f), whichever is less.
double room_for(const std::filesystem::path& directory, const std::filesystem::path& file) {
  double room = std::numeric_limits<double>::infinity();
  struct statvfs disk {};
  if (statvfs(directory.c_str(), &disk) == 0) {
    room = static_cast<double>(disk.f_bavail) * static_cast<double>(disk.f_frsize);
  }
  struct rlimit limit {};
  if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    std::error_code error;
    const auto size = std::filesystem::file_size(file, error);
    room = std::min(room, static_cast<double>(limit.rlim_cur) - (error ? 0.0 : double(size)));
  }
  return room;
}

// A frame's fields in order, "name/node" or "name/cell" joined by commas (the frame group's
// attribute `fields`): what a restart needs to list the frame again in the .xdmf.
std::string field_list(const std::vector<FieldView>& fields) {
  std::string list;
  for (const FieldView& field : fields) {
    list += (list.empty() ? "" : ",") + field.name +
            (field.center == FieldCenter::cell ? "/cell" : "/node");
  }
  return list;
}

// Flushes `file` to the disk (HDF5 1.10's default driver does not), so that what the commit
// record or an .xdmf names survives a power loss as well as a kill.
void sync_to_disk(const std::filesystem::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const std::error_code error(errno, std::generic_category());
    if (fd >= 0) {
      ::close(fd);
    }
    throw std::runtime_error("cannot flush '" + file.string() +
                             "' to the disk: " + error.message());
  }
  ::close(fd);
}

// A name for this run that another run will not have: the clock and the process.
std::string new_run_id() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return std::to_string(std::chrono::duration_cast<std::chrono::nanoseconds>(now).count()) + "-" +
         std::to_string(static_cast<long>(getpid()));
}

}  // namespace

std::string frame_group_name(int index) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%06d", index);
  return buffer;
}

void ResultsWriter::check_layout(const std::vector<PartTopology>& parts,
                                 const std::vector<std::string>& history_columns) {
  std::set<std::string> seen;
  for (const PartTopology& part : parts) {
    check_name(part.name, "part name");
    if (!seen.insert(part.name).second) {
      throw std::invalid_argument("part '" + part.name + "' is given twice");
    }
    if (part.nodes_per_cell != 3 && part.nodes_per_cell != 4) {
      throw std::invalid_argument("part '" + part.name + "': nodes per cell must be 3 or 4, not " +
                                  std::to_string(part.nodes_per_cell));
    }
    if (part.cells.rows() != part.nodes_per_cell) {
      throw std::invalid_argument("part '" + part.name + "': connectivity has " +
                                  std::to_string(part.cells.rows()) + " rows, expected " +
                                  std::to_string(part.nodes_per_cell));
    }
    if (part.triangles.cols() > 0 && part.nodes_per_cell != 4) {
      throw std::invalid_argument("part '" + part.name +
                                  "': extra triangles are allowed only after quadrilaterals");
    }
    const Eigen::Index node_count = part.reference_nodes.cols();
    if ((part.cells.size() > 0 &&
         (part.cells.minCoeff() < 0 || part.cells.maxCoeff() >= node_count)) ||
        (part.triangles.size() > 0 &&
         (part.triangles.minCoeff() < 0 || part.triangles.maxCoeff() >= node_count))) {
      throw std::invalid_argument("part '" + part.name +
                                  "': connectivity refers to a node outside 0.." +
                                  std::to_string(node_count - 1));
    }
  }
  seen.clear();
  for (const std::string& column : history_columns) {
    check_name(column, "history column");
    if (!seen.insert(column).second) {
      throw std::invalid_argument("history column '" + column + "' is given twice");
    }
  }
}

XdmfPart ResultsWriter::describe_grid(const PartTopology& part, const std::string& path) {
  const auto cells = static_cast<std::size_t>(part.cells.cols());
  const auto triangles = static_cast<std::size_t>(part.triangles.cols());
  XdmfPart grid;
  grid.name = part.name;
  grid.nodes_per_cell = part.nodes_per_cell;
  grid.node_count = static_cast<std::size_t>(part.reference_nodes.cols());
  grid.cell_count = cells + triangles;
  grid.connectivity_dataset = path + "/connectivity";
  if (triangles > 0) {
    // Mixed: the flat XDMF "Mixed" array (type code, then the nodes, per cell).
    grid.connectivity_dataset = path + "/mixed_connectivity";
    grid.mixed_connectivity_size = 5 * cells + 4 * triangles;
  }
  return grid;
}

ResultsWriter::PartRecord ResultsWriter::describe_part(const PartTopology& part) {
  PartRecord record;
  record.grid = describe_grid(part, part_path(part.name));
  return record;
}

void ResultsWriter::set_directory(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw InputError("cannot create results directory '" + directory.string() +
                     "': " + error.message());
  }
  directory_ = std::filesystem::absolute(directory).lexically_normal();
}

ResultsWriter::ResultsWriter(const std::filesystem::path& directory,
                             std::vector<PartTopology> parts,
                             std::vector<std::string> history_columns,
                             std::vector<std::string> history_units)
    : history_columns_(std::move(history_columns)) {
  if (!history_units.empty() && history_units.size() != history_columns_.size()) {
    throw std::invalid_argument(std::to_string(history_units.size()) + " history unit(s) for " +
                                std::to_string(history_columns_.size()) + " column(s)");
  }
  // Check everything before touching the disk.
  check_layout(parts, history_columns_);
  set_directory(directory);
  run_id_ = new_run_id();
  for (const PartTopology& part : parts) {
    parts_.push_back(describe_part(part));
  }
  run_detached([&] {
    create_file(parts, history_units);
    write_xdmf_files();
  });
}

void ResultsWriter::create_file(const std::vector<PartTopology>& parts,
                                const std::vector<std::string>& history_units) const {
  try {
    h5::File file(results_file(), h5::FileMode::truncate);
    file.write_attribute("/", "format", std::string("sheetform results"));
    file.write_attribute("/", "format_version", format_version);
    file.create_group("/parts");
    file.write_attribute("/parts", frames_attribute, 0);
    for (const PartTopology& part : parts) {
      const std::string path = part_path(part.name);
      write_topology(file, path, part);
      file.create_group(path + "/frames");
    }
    file.create_group("/history");
    std::string column_list;
    for (std::size_t c = 0; c < history_columns_.size(); ++c) {
      const std::string& column = history_columns_[c];
      file.create_extendible("/history/" + column, history_chunk_rows);
      if (!history_units.empty()) {
        file.write_attribute("/history/" + column, "unit", history_units[c]);
      }
      column_list += (column_list.empty() ? "" : ",") + column;
    }
    file.write_attribute("/history", "columns", column_list);
    file.create_group("/run");
    file.write_attribute("/run", "run_id", run_id_);
    file.close();
  } catch (const h5::Error& e) {
    throw InputError("cannot write results in '" + directory_.string() + "': " + e.what());
  }
}

void ResultsWriter::write_topology(h5::File& file, const std::string& path,
                                   const PartTopology& part) {
  const hsize_t cells = to_hsize(part.cells.cols());
  const hsize_t nodes = to_hsize(part.reference_nodes.cols());
  file.write(path + "/connectivity",
             std::span<const int>(part.cells.data(), static_cast<std::size_t>(part.cells.size())),
             {cells, static_cast<hsize_t>(part.nodes_per_cell)});
  file.write(path + "/reference_coordinates",
             std::span<const double>(part.reference_nodes.data(),
                                     static_cast<std::size_t>(part.reference_nodes.size())),
             {nodes, 3});
  const hsize_t triangles = to_hsize(part.triangles.cols());
  if (triangles > 0) {
    file.write(path + "/triangle_connectivity",
               std::span<const int>(part.triangles.data(),
                                    static_cast<std::size_t>(part.triangles.size())),
               {triangles, 3});
    std::vector<int> mixed;
    mixed.reserve(static_cast<std::size_t>(5 * cells + 4 * triangles));
    for (Eigen::Index e = 0; e < part.cells.cols(); ++e) {
      mixed.push_back(kXdmfQuadrilateral);
      for (int a = 0; a < 4; ++a) {
        mixed.push_back(part.cells(a, e));
      }
    }
    for (Eigen::Index k = 0; k < part.triangles.cols(); ++k) {
      mixed.push_back(kXdmfTriangle);
      for (int a = 0; a < 3; ++a) {
        mixed.push_back(part.triangles(a, k));
      }
    }
    file.write(path + "/mixed_connectivity", std::span<const int>(mixed), {mixed.size()});
  }
  // 4 quadrilaterals, 3 triangles, 0 mixed (quadrilaterals, then triangles).
  file.write_attribute(path, "nodes_per_cell", triangles > 0 ? 0 : part.nodes_per_cell);
}

void ResultsWriter::change_topology(const PartTopology& part) {
  check_layout({part}, {});
  PartRecord& record = parts_[part_index(part.name)];
  const int topology = record.topology + 1;
  const std::string path = topology_path(part.name, topology);
  writing(directory_, [&] {
    run_detached([&] {
      h5::File file(results_file(), h5::FileMode::read_write);
      if (file.exists(path)) {
        file.remove(path);  // left by a run a restart goes on from
      }
      write_topology(file, path, part);
      file.write_attribute(path, "first_frame", frame_count_);
      file.close();
    });
  });
  record.topology = topology;
  record.current_grid = std::make_shared<const XdmfPart>(describe_grid(part, path));
}

ResultsWriter::ResultsWriter(const std::filesystem::path& directory,
                             std::vector<PartTopology> parts,
                             std::vector<std::string> history_columns, const Resume& resume)
    : history_columns_(std::move(history_columns)) {
  check_layout(parts, history_columns_);
  directory_ = std::filesystem::absolute(directory).lexically_normal();
  for (const PartTopology& part : parts) {
    parts_.push_back(describe_part(part));
  }
  const std::string where = results_file().string();
  if (!std::filesystem::exists(results_file())) {
    throw InputError(where +
                     ": missing; a restart goes on writing the results of the run its "
                     "checkpoint comes from (give that run's results folder with -o)");
  }
  try {
    const h5::File file(results_file(), h5::FileMode::read_only);
    run_id_ = file.exists("/run") ? file.read_attribute_string("/run", "run_id") : "";
    if (run_id_ != resume.run_id) {
      throw InputError(where + ": holds the results of another run (run " + run_id_ +
                       ") than the checkpoint's (run " + resume.run_id +
                       "); give the checkpoint's own results folder with -o");
    }
    read_kept_frames(file, resume);
  } catch (const h5::Error& e) {
    throw InputError(where + ": cannot take up the results for the restart: " + e.what());
  }
  run_detached([&] {
    try {
      h5::File file(results_file(), h5::FileMode::read_write);
      drop_later_output(file, resume);
    } catch (const h5::Error& e) {
      throw InputError(where + ": cannot take up the results for the restart: " + e.what());
    }
    write_xdmf_files();
  });
}

void ResultsWriter::read_kept_frames(const h5::File& file, const Resume& resume) {
  const std::string where = results_file().string();
  // A file written before the commit record counts every frame group it has.
  const int committed = file.has_attribute("/parts", frames_attribute)
                            ? file.read_attribute_int("/parts", frames_attribute)
                            : resume.frames;
  for (PartRecord& record : parts_) {
    const std::string frames = part_path(record.grid.name) + "/frames";
    if (!file.exists(frames)) {
      throw InputError(where + ": has no part '" + record.grid.name + "' (another case's results)");
    }
    record.grid = stored_grid(file, record.grid.name, part_path(record.grid.name));
    for (int index = 0; index < resume.frames; ++index) {
      const std::string group = frame_path(record.grid.name, index);
      if (index >= committed || !file.exists(group)) {
        throw InputError(where + ": frame " + std::to_string(index) + " of part '" +
                         record.grid.name + "' is missing; the checkpoint expects " +
                         std::to_string(resume.frames) + " frames");
      }
      XdmfFrame frame;
      frame.time = file.read_attribute_double(group, "time");
      frame.cycle = file.read_attribute_int(group, "cycle");
      frame.coordinates_dataset = group + "/coordinates";
      for (const std::string& entry :
           split_comma_list(file.read_attribute_string(group, "fields"))) {
        const std::size_t slash = entry.rfind('/');
        XdmfAttribute attribute;
        attribute.name = entry.substr(0, slash);
        attribute.center =
            entry.substr(slash + 1) == "cell" ? FieldCenter::cell : FieldCenter::node;
        attribute.dataset = group + "/" + attribute.name;
        const std::vector<hsize_t> shape = file.shape(attribute.dataset);
        attribute.components = shape.size() == 2 ? static_cast<int>(shape[1]) : 1;
        frame.attributes.push_back(std::move(attribute));
      }
      if (file.has_attribute(group, "topology")) {
        // a frame after a trim: its own mesh
        const int topology = file.read_attribute_int(group, "topology");
        if (topology != record.topology) {
          record.topology = topology;
          record.current_grid = std::make_shared<const XdmfPart>(
              stored_grid(file, record.grid.name, topology_path(record.grid.name, topology)));
        }
        frame.grid = record.current_grid;
      }
      last_time_ = frame.time;
      record.frames.push_back(std::move(frame));
    }
  }
  frame_count_ = resume.frames;
  for (const std::string& column : history_columns_) {
    const std::string path = "/history/" + column;
    if (!file.exists(path) || file.shape(path).at(0) < resume.history_rows) {
      throw InputError(where + ": history column '" + column + "' is missing or holds fewer than " +
                       std::to_string(resume.history_rows) + " rows (another case's results)");
    }
  }
  history_rows_written_ = resume.history_rows;
}

void ResultsWriter::drop_later_output(h5::File& file, const Resume& resume) const {
  for (const PartRecord& record : parts_) {
    // Frames the run wrote after its checkpoint: the restart writes them again.
    const std::string frames = part_path(record.grid.name) + "/frames";
    for (const std::string& name : file.list(frames)) {
      if (std::stoi(name) >= resume.frames) {
        file.remove(frames + "/" + name);
      }
    }
    // Meshes of trims after the checkpoint: the restart trims again.
    const std::string topologies = part_path(record.grid.name) + "/topologies";
    if (file.exists(topologies)) {
      for (const std::string& name : file.list(topologies)) {
        const std::string path = topologies + "/" + name;
        if (file.read_attribute_int(path, "first_frame") >= resume.frames) {
          file.remove(path);
        }
      }
    }
  }
  for (const std::string& column : history_columns_) {
    file.write_rows("/history/" + column, resume.history_rows, {});  // drops the later rows
  }
  commit_frames(file, resume.frames);
}

ResultsWriter::~ResultsWriter() {
  try {
    flush_history();
  } catch (const std::exception& e) {
    log_warning("history rows not written: {}\n", e.what());
  }
}

int ResultsWriter::first_frame_at_or_after(double time) const {
  if (parts_.empty()) {
    return frame_count_;
  }
  const std::vector<XdmfFrame>& frames = parts_.front().frames;
  const auto at = std::find_if(frames.begin(), frames.end(),
                               [time](const XdmfFrame& f) { return f.time >= time; });
  return static_cast<int>(at - frames.begin());
}

std::filesystem::path ResultsWriter::xdmf_file(const std::string& part) const {
  return directory_ / (part + ".xdmf");
}

const ResultsWriter::PartRecord& ResultsWriter::find_part(const std::string& name) const {
  return parts_[part_index(name)];
}

std::size_t ResultsWriter::part_index(const std::string& name) const {
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    if (parts_[i].grid.name == name) {
      return i;
    }
  }
  throw std::invalid_argument("results: unknown part '" + name + "'");
}

void ResultsWriter::check_frame(double time, const std::vector<PartFrameView>& parts) const {
  const std::string frame = "results frame " + std::to_string(frame_count_);
  if (!std::isfinite(time) || (frame_count_ > 0 && !(time > last_time_))) {
    throw std::invalid_argument(frame + ": time " + std::to_string(time) +
                                " must be finite and greater than the previous frame's " +
                                std::to_string(last_time_));
  }
  if (parts.size() != parts_.size()) {
    throw std::invalid_argument(frame + ": " + std::to_string(parts.size()) +
                                " part(s) given, expected every one of the " +
                                std::to_string(parts_.size()) + " parts once");
  }
  std::set<std::string> seen_parts;
  for (const PartFrameView& view : parts) {
    const PartRecord& record = find_part(view.part);
    if (!seen_parts.insert(view.part).second) {
      throw std::invalid_argument(frame + ": part '" + view.part + "' given twice");
    }
    if (static_cast<std::size_t>(view.coordinates.cols()) != record.now().node_count) {
      throw std::invalid_argument(
          frame + ", part '" + view.part + "': " + std::to_string(view.coordinates.cols()) +
          " node coordinates, expected " + std::to_string(record.now().node_count));
    }
    std::set<std::string> seen_fields;
    for (const FieldView& field : view.fields) {
      const std::string where = frame + ", part '" + view.part + "', field '" + field.name + "'";
      check_name(field.name, frame + ", part '" + view.part + "': field");
      if (field.name == "coordinates" || !seen_fields.insert(field.name).second) {
        throw std::invalid_argument(where + ": name reserved or given twice");
      }
      if (field.components != 1 && field.components != 3 && field.components != 6) {
        throw std::invalid_argument(where + ": " + std::to_string(field.components) +
                                    " components; expected 1, 3 or 6");
      }
      if (field.data == nullptr) {
        throw std::invalid_argument(where + ": no data");
      }
    }
  }
}

void ResultsWriter::write_frame(double time, int cycle, const std::vector<PartFrameView>& parts) {
  check_frame(time, parts);
  check_room(parts);
  writing(directory_, [&] { write_checked_frame(time, cycle, parts); });
}

void ResultsWriter::check_room(const std::vector<PartFrameView>& parts) const {
  // HDF5 cannot open a file it grew for a write that then failed (a full disk), so a frame is
  // written only when twice its size and 1 MB fit; a disk filling up stops the run readable.
  double bytes = 8.0 * static_cast<double>(history_buffer_.size()) + 1e6;
  for (const PartFrameView& view : parts) {
    const XdmfPart& grid = find_part(view.part).now();
    bytes += 24.0 * static_cast<double>(grid.node_count);
    for (const FieldView& field : view.fields) {
      const std::size_t rows =
          field.center == FieldCenter::node ? grid.node_count : grid.cell_count;
      bytes += 8.0 * static_cast<double>(rows) * field.components;
    }
  }
  const double room = room_for(directory_, results_file());
  if (room < 2.0 * bytes) {
    throw OutputError(fmt::format(
        "cannot write the results in {}: the disk is full ({:.1f} MB left, a frame needs about "
        "{:.1f} MB)",
        directory_.string(), std::max(room, 0.0) / 1e6, bytes / 1e6));
  }
}

void ResultsWriter::write_checked_frame(double time, int cycle,
                                        const std::vector<PartFrameView>& parts) {
  const std::vector<XdmfFrame> frames = describe_frame(time, cycle, parts);
  run_detached([&] {
    store_frame(frames, parts);
    write_xdmf_files(&frames);  // the frame is committed: only now may the .xdmf files list it
  });
  commit_history();
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    parts_[i].frames.push_back(frames[i]);
  }
  frame_count_ += 1;
  last_time_ = time;
}

std::vector<XdmfFrame> ResultsWriter::describe_frame(
    double time, int cycle, const std::vector<PartFrameView>& parts) const {
  std::vector<XdmfFrame> frames(parts_.size());
  for (const PartFrameView& view : parts) {
    XdmfFrame& frame = frames[part_index(view.part)];
    const std::string group = frame_path(view.part, frame_count_);
    frame.time = time;
    frame.cycle = cycle;
    frame.coordinates_dataset = group + "/coordinates";
    frame.grid = parts_[part_index(view.part)].current_grid;
    for (const FieldView& field : view.fields) {
      frame.attributes.push_back(
          XdmfAttribute{field.name, field.center, field.components, group + "/" + field.name});
    }
  }
  return frames;
}

void ResultsWriter::store_frame(const std::vector<XdmfFrame>& frames,
                                const std::vector<PartFrameView>& parts) const {
  h5::File file(results_file(), h5::FileMode::read_write);
  for (const PartFrameView& view : parts) {
    const std::size_t index = part_index(view.part);
    const XdmfPart& grid = parts_[index].now();
    const XdmfFrame& frame = frames[index];
    const std::string group = frame_path(view.part, frame_count_);
    if (file.exists(group)) {
      file.remove(group);  // left by a write that failed (or was cut) half-way
    }
    file.write(frame.coordinates_dataset,
               std::span<const double>(view.coordinates.data(), grid.node_count * 3),
               {grid.node_count, 3});
    for (std::size_t f = 0; f < view.fields.size(); ++f) {
      const FieldView& field = view.fields[f];
      const std::size_t rows =
          field.center == FieldCenter::node ? grid.node_count : grid.cell_count;
      const auto columns = static_cast<std::size_t>(field.components);
      file.write(frame.attributes[f].dataset, std::span<const double>(field.data, rows * columns),
                 {rows, columns});
    }
    file.write_attribute(group, "time", frame.time);
    file.write_attribute(group, "cycle", frame.cycle);
    file.write_attribute(group, "fields", field_list(view.fields));
    if (parts_[index].topology > 0) {
      file.write_attribute(group, "topology", parts_[index].topology);
    }
  }
  write_history_rows(file);
  commit_frames(file, frame_count_ + 1);
}

void ResultsWriter::commit_frames(h5::File& file, int frames) const {
  // The count is written last, in place (one block of the file), once what it counts is on the
  // disk (a power loss cannot leave a count of frames that are not there); the .xdmf files,
  // flushed to the disk each, follow it (write_xdmf_files after this returns).
  file.flush();
  sync_to_disk(results_file());
  file.write_attribute("/parts", frames_attribute, frames);
  file.close();
}

void ResultsWriter::append_history(std::span<const double> row) {
  if (row.size() != history_columns_.size()) {
    throw std::invalid_argument("history row with " + std::to_string(row.size()) +
                                " value(s), expected " + std::to_string(history_columns_.size()) +
                                " (one per history column)");
  }
  history_buffer_.insert(history_buffer_.end(), row.begin(), row.end());
}

void ResultsWriter::flush_history() {
  if (history_buffer_.empty()) {
    return;
  }
  writing(directory_, [&] {
    run_detached([&] {
      h5::File file(results_file(), h5::FileMode::read_write);
      write_history_rows(file);
      file.close();
    });
    commit_history();
  });
}

std::size_t ResultsWriter::buffered_history_rows() const {
  return history_columns_.empty() ? 0 : history_buffer_.size() / history_columns_.size();
}

void ResultsWriter::write_history_rows(h5::File& file) const {
  const std::size_t columns = history_columns_.size();
  const std::size_t rows = buffered_history_rows();
  if (rows == 0) {
    return;
  }
  std::vector<double> column_values(rows);
  for (std::size_t c = 0; c < columns; ++c) {
    for (std::size_t r = 0; r < rows; ++r) {
      column_values[r] = history_buffer_[r * columns + c];
    }
    // Written at a fixed offset, so a retry after a failure does not duplicate rows.
    file.write_rows("/history/" + history_columns_[c], history_rows_written_, column_values);
  }
}

void ResultsWriter::commit_history() {
  history_rows_written_ += buffered_history_rows();
  history_buffer_.clear();
}

void ResultsWriter::write_run_info(const std::string& key, const std::string& text) {
  check_name(key, "run information key");
  writing(directory_, [&] {
    run_detached([&] {
      h5::File file(results_file(), h5::FileMode::read_write);
      const std::string path = "/run/" + key;
      if (file.exists(path)) {
        file.remove(path);
      }
      file.write_string(path, text);
      file.close();
    });
  });
}

void ResultsWriter::write_operation(int index, const OperationRecord& r) {
  writing(directory_, [&] {
    run_detached([&] {
      h5::File file(results_file(), h5::FileMode::read_write);
      if (!file.exists("/operations")) {
        file.create_group("/operations");
      }
      const std::string path = "/operations/" + std::to_string(index);
      if (file.exists(path)) {
        file.remove(path);
      }
      file.create_group(path);
      file.write_attribute(path, "name", r.name);
      file.write_attribute(path, "kind", r.kind);
      file.write_attribute(path, "ended_by", r.ended_by);
      file.write_attribute(path, "start_time", r.start_time);
      file.write_attribute(path, "end_time", r.end_time);
      file.write_attribute(path, "start_cycle", static_cast<double>(r.start_cycle));
      file.write_attribute(path, "end_cycle", static_cast<double>(r.end_cycle));
      file.write_attribute(path, "first_frame", r.first_frame);
      file.write_attribute(path, "last_frame", r.last_frame);
      file.write_attribute(path, "wall_seconds", r.wall_seconds);
      file.close();
    });
  });
}

std::vector<OperationRecord> ResultsWriter::read_operations(int count) const {
  std::vector<OperationRecord> records;
  const h5::File file(results_file(), h5::FileMode::read_only);
  for (int index = 0; index < count; ++index) {
    const std::string path = "/operations/" + std::to_string(index);
    if (!file.exists(path)) {
      throw InputError(results_file().string() + ": has no record " + path +
                       " of an operation the checkpoint has passed (another run's results?)");
    }
    OperationRecord r;
    r.name = file.read_attribute_string(path, "name");
    r.kind = file.read_attribute_string(path, "kind");
    r.ended_by = file.read_attribute_string(path, "ended_by");
    r.start_time = file.read_attribute_double(path, "start_time");
    r.end_time = file.read_attribute_double(path, "end_time");
    r.start_cycle = static_cast<long>(file.read_attribute_double(path, "start_cycle"));
    r.end_cycle = static_cast<long>(file.read_attribute_double(path, "end_cycle"));
    r.first_frame = file.read_attribute_int(path, "first_frame");
    r.last_frame = file.read_attribute_int(path, "last_frame");
    r.wall_seconds = file.read_attribute_double(path, "wall_seconds");
    records.push_back(std::move(r));
  }
  return records;
}

void ResultsWriter::write_xdmf_files(const std::vector<XdmfFrame>* pending) const {
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    const PartRecord& record = parts_[i];
    std::vector<XdmfFrame> frames = record.frames;
    if (pending != nullptr) {
      frames.push_back((*pending)[i]);
    }
    write_file_atomically(xdmf_file(record.grid.name),
                          make_xdmf(record.grid, frames, results_file_name));
  }
}

}  // namespace sf

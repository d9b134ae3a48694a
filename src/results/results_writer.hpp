#pragma once
// Results of a run: one HDF5 file (results.h5) with every part's meshes and output frames, the
// history (energies, forces, ... one row per history step) and run information, plus one XDMF 3
// file per part for ParaView. The layout is described in docs/results-format.md.
//
// Crash safety: results.h5 is open only while a frame (or history, or run information) is being
// written and is closed after it. A frame's write goes: its datasets and the history rows, on the
// disk; then the commit record, results.h5's frame count (/parts attribute "frames"); then every
// .xdmf, replaced atomically. Each write runs in a detached child process (run_detached), so a
// run killed at any moment leaves results.h5 and the .xdmf files agreeing on the frames, with no
// temporary file (docs/results-format.md, "Running and killed jobs").
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "results/xdmf_writer.hpp"

namespace sf {

namespace h5 {
class File;
}

/// A field of one part at one frame, borrowed from the caller for the duration of write_frame.
/// Values are in the case's units (forming cases: mm, s, tonne, N, MPa).
struct FieldView {
  /// Array name (letters, digits, '_', '-', '.'; not "coordinates"), e.g. displacement (mm),
  /// velocity (mm/s), contact_force (N), thickness (mm), plastic_strain (-), stress_mid,
  /// stress_top, stress_bottom (MPa).
  std::string name;
  FieldCenter center = FieldCenter::node;
  /// Values per node or cell: 1 scalar, 3 vector, 6 symmetric tensor (xx, yy, zz, xy, yz, xz).
  int components = 1;
  /// `components` consecutive values per node or cell (column-major, as in a Matrix3X), for
  /// every node or every cell of the part.
  const double* data = nullptr;
};

/// Static description of a part.
struct PartTopology {
  std::string name;        ///< part name (letters, digits, '_', '-', '.'); names <name>.xdmf
  int nodes_per_cell = 4;  ///< 3 = triangle, 4 = quadrilateral
  /// Node indices (0-based), one column per cell, nodes_per_cell rows.
  Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic> cells;
  /// A mixed part (nodes_per_cell = 4 only): triangles that follow the quadrilaterals `cells`,
  /// so the part's cells are cells.cols() quads, then these triangles (cell fields in that
  /// order). Empty for a part of one cell type.
  TriConn triangles;
  Matrix3X reference_nodes;  ///< mm, column per node: the coordinates at time 0
};

/// One part at one output frame.
struct PartFrameView {
  std::string part;               ///< a name given to the ResultsWriter
  const Matrix3X& coordinates;    ///< mm, current coordinates, column per node
  std::vector<FieldView> fields;  ///< any number, each name once
};

/// Writes results.h5 and <part>.xdmf files into one directory. Use from one thread.
///
/// Errors: a results directory that cannot be created or written throws sf::InputError naming
/// the path; invalid arguments (unknown part, wrong sizes, bad names, time not increasing) throw
/// std::invalid_argument before anything is written; a failure to write a frame, history rows or
/// run information (a full disk) throws sf::OutputError naming the file and the system's reason.
/// One operation of the press line as run (results.h5 /operations/<index>, summary.json).
struct OperationRecord {
  std::string name;
  std::string kind;         ///< "gravity", "closing", "forming", "springback"
  std::string ended_by;     ///< what ended it, in words ("stroke 20 mm of 'punch'")
  double start_time = 0.0;  ///< s
  double end_time = 0.0;    ///< s
  long start_cycle = 0;
  long end_cycle = 0;
  int first_frame = 0;        ///< the first frame at or after its start
  int last_frame = 0;         ///< the frame of its end
  double wall_seconds = 0.0;  ///< s, its wall time
};

class ResultsWriter {
 public:
  /// Creates `directory` (and its parents) if missing, creates or truncates
  /// <directory>/results.h5 with every part's topology, /history and /run, and writes one
  /// <directory>/<part>.xdmf per part, with no frames yet. `history_columns` names the history
  /// values (time first, by convention), e.g. time (s), kinetic_energy (mJ), punch_force (N).
  /// `history_units`, when given, holds one unit per column ("mm", "N", "-"), stored as the
  /// string attribute `unit` of each /history/<column>.
  ResultsWriter(const std::filesystem::path& directory, std::vector<PartTopology> parts,
                std::vector<std::string> history_columns,
                std::vector<std::string> history_units = {});
  /// Where a run continued from a checkpoint takes up its results: the frames and history rows
  /// results.h5 held when the checkpoint was written, and the run it belongs to.
  struct Resume {
    int frames = 0;
    std::size_t history_rows = 0;
    std::string run_id;
  };
  /// Opens the existing <directory>/results.h5 of the same parts and history columns to go on
  /// writing it: frames and history rows written after `resume` (by the run after its
  /// checkpoint) are dropped, the .xdmf files rewritten to list the frames kept. Throws
  /// InputError naming the file when it is missing, of another run, or holds fewer frames or
  /// rows than `resume`.
  ResultsWriter(const std::filesystem::path& directory, std::vector<PartTopology> parts,
                std::vector<std::string> history_columns, const Resume& resume);
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;
  /// Flushes buffered history rows (errors are reported as a warning, not thrown).
  ~ResultsWriter();

  /// Writes output frame number frame_count(): per part its current coordinates and fields,
  /// at `time` (s, strictly greater than the previous frame's) and explicit cycle `cycle`.
  /// Every part must appear exactly once. Opens results.h5, writes the frame and the buffered
  /// history rows, closes it, then rewrites every part's .xdmf atomically.
  void write_frame(double time, int cycle, const std::vector<PartFrameView>& parts);

  /// Buffers one history row: one value per history column, in the columns' order. Buffered
  /// rows reach /history at the next write_frame or flush_history.
  void append_history(std::span<const double> row);
  /// Writes the buffered history rows to results.h5 now (opens and closes the file).
  void flush_history();

  /// From the next frame on, the part named `part.name` has this mesh (a trim removed elements
  /// and nodes): it is kept in results.h5 as /parts/<name>/topologies/<k> (k = 1, 2, ... per
  /// change, attribute first_frame) and each later frame group carries the attribute topology =
  /// k; every frame's .xdmf grid names its own mesh, so ParaView plays through the change.
  /// Throws std::invalid_argument for an unknown part or a bad mesh, OutputError when the file
  /// cannot be written.
  void change_topology(const PartTopology& part);

  /// Stores `text` (e.g. the resolved case, the version) as the string dataset /run/<key>,
  /// replacing an earlier one of the same key.
  void write_run_info(const std::string& key, const std::string& text);

  /// Writes operation number `index`'s record as the group /operations/<index> (attributes; one
  /// written before, by a run a restart goes on from, is replaced).
  void write_operation(int index, const OperationRecord& record);
  /// The records of operations 0 .. count - 1 as written (a restart inside operation `count`
  /// reports the ones before it); InputError naming the file when one is missing.
  std::vector<OperationRecord> read_operations(int count) const;

  /// The identity of the run that created results.h5 (attribute run_id of /run): a restart
  /// checks that its checkpoint belongs to the same run.
  const std::string& run_id() const { return run_id_; }
  /// Number of frames written so far.
  int frame_count() const { return frame_count_; }
  /// The first frame at or after `time` (s) among those written (frame_count() if none is).
  int first_frame_at_or_after(double time) const;
  /// History rows written to results.h5 so far (not counting buffered ones).
  std::size_t history_rows_written() const { return history_rows_written_; }
  /// Absolute path of the results directory.
  const std::filesystem::path& directory() const { return directory_; }
  /// Absolute path of results.h5.
  std::filesystem::path results_file() const { return directory_ / "results.h5"; }
  /// Absolute path of <part>.xdmf.
  std::filesystem::path xdmf_file(const std::string& part) const;

 private:
  struct PartRecord {
    XdmfPart grid;                                 ///< the grid of the part's first mesh
    int topology = 0;                              ///< how many times its mesh changed
    std::shared_ptr<const XdmfPart> current_grid;  ///< the grid after a change (null: none yet)
    std::vector<XdmfFrame> frames;                 ///< one per frame written
    /// The grid of the part's mesh now.
    const XdmfPart& now() const { return current_grid ? *current_grid : grid; }
  };

  static void check_layout(const std::vector<PartTopology>& parts,
                           const std::vector<std::string>& history_columns);
  static XdmfPart describe_grid(const PartTopology& part, const std::string& path);
  static PartRecord describe_part(const PartTopology& part);
  /// Writes a mesh's datasets into the group `path`.
  static void write_topology(h5::File& file, const std::string& path, const PartTopology& part);
  void set_directory(const std::filesystem::path& directory);
  /// Creates results.h5 with the parts' topology, no frames and empty history columns.
  void create_file(const std::vector<PartTopology>& parts,
                   const std::vector<std::string>& history_units) const;
  /// Reads back the frames a restart keeps, after checking the file against `resume`.
  void read_kept_frames(const h5::File& file, const Resume& resume);
  /// Drops the frames and history rows a run wrote after its checkpoint.
  void drop_later_output(h5::File& file, const Resume& resume) const;
  const PartRecord& find_part(const std::string& name) const;
  std::size_t part_index(const std::string& name) const;
  void check_frame(double time, const std::vector<PartFrameView>& parts) const;
  void check_room(const std::vector<PartFrameView>& parts) const;
  void write_checked_frame(double time, int cycle, const std::vector<PartFrameView>& parts);
  /// The .xdmf description of frame frame_count(), one per part in the writer's part order.
  std::vector<XdmfFrame> describe_frame(double time, int cycle,
                                        const std::vector<PartFrameView>& parts) const;
  /// Writes frame frame_count() and the buffered history rows, then commits the frame.
  void store_frame(const std::vector<XdmfFrame>& frames,
                   const std::vector<PartFrameView>& parts) const;
  /// Sets results.h5's frame count to `frames` once everything before is on the disk; closes.
  void commit_frames(h5::File& file, int frames) const;
  /// The whole rows in the history buffer (not yet in results.h5).
  std::size_t buffered_history_rows() const;
  /// Writes the buffered rows into the open file (commit_history once the write is done).
  void write_history_rows(h5::File& file) const;
  /// Counts the buffered rows as written and empties the buffer.
  void commit_history();
  /// Replaces every part's .xdmf: its frames, and `pending`'s (one per part) when given.
  void write_xdmf_files(const std::vector<XdmfFrame>* pending = nullptr) const;

  std::filesystem::path directory_;
  std::vector<PartRecord> parts_;
  std::vector<std::string> history_columns_;
  std::vector<double> history_buffer_;  ///< buffered rows, row after row
  std::size_t history_rows_written_ = 0;
  int frame_count_ = 0;
  double last_time_ = 0.0;
  std::string run_id_;
};

/// The name of frame `index`'s group: zero-padded to 6 digits ("000003").
std::string frame_group_name(int index);

}  // namespace sf

#pragma once
// XDMF 3 text for one part: a temporal collection with one Uniform grid per output frame, every
// heavy array a DataItem pointing into the HDF5 results file. This is the form ParaView 5.11's
// Xdmf3ReaderS reads as a time series (see docs/results-format.md).
#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sf {

/// Where a field's values live: one tuple per node or one per cell.
enum class FieldCenter { node, cell };

/// One XDMF Attribute: a field stored as an HDF5 dataset of shape [rows][components].
struct XdmfAttribute {
  std::string name;  ///< array name shown by ParaView
  FieldCenter center = FieldCenter::node;
  int components = 1;   ///< 1 Scalar, 3 Vector, 6 Tensor6 (xx, yy, zz, xy, yz, xz)
  std::string dataset;  ///< absolute HDF5 path of the data
};

struct XdmfPart;

/// One output frame of a part.
struct XdmfFrame {
  double time = 0.0;                ///< s (case units)
  int cycle = 0;                    ///< explicit cycle number
  std::string coordinates_dataset;  ///< HDF5 path of the [nodes][3] current coordinates
  std::vector<XdmfAttribute> attributes;
  /// The frame's own grid where the part's mesh changed (a trim, solver/trim.hpp); null: the
  /// part's grid given to make_xdmf.
  std::shared_ptr<const XdmfPart> grid;
};

/// The description of a part's grid.
struct XdmfPart {
  std::string name;        ///< part name, also the collection's name
  int nodes_per_cell = 4;  ///< 3 (Triangle) or 4 (Quadrilateral); ignored for a mixed part
  std::size_t node_count = 0;
  std::size_t cell_count = 0;
  std::string connectivity_dataset;  ///< HDF5 path of the [cells][nodes_per_cell] int32 array
  /// A mixed part (TopologyType "Mixed"): the length of the flat int32 connectivity array, in
  /// which each cell is its XDMF type code (5 Quadrilateral, 4 Triangle) followed by its nodes;
  /// connectivity_dataset then names that array. 0 for a part of one cell type.
  std::size_t mixed_connectivity_size = 0;
};

/// XDMF 3 cell type codes used in a "Mixed" topology's connectivity.
inline constexpr int kXdmfTriangle = 4;
inline constexpr int kXdmfQuadrilateral = 5;

/// The XDMF 3 document for `part` with the given frames, in order. `h5_file` is the HDF5 file as
/// DataItems name it: a name relative to the .xdmf file's folder (ParaView 5.11 resolves it
/// there) or an absolute path. Times are written with the shortest text that reads back to the
/// same double.
std::string make_xdmf(const XdmfPart& part, std::span<const XdmfFrame> frames,
                      const std::string& h5_file);

/// Replaces `path` by `text` atomically: writes "<path>.tmp", flushes it to disk (fsync), then
/// renames it over `path`, so a reader (or a killed run) sees either the old or the new file,
/// never a partial one. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view text);

}  // namespace sf

#include "results/xdmf_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <system_error>

namespace sf {
namespace {

std::string escape_xml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

/// Shortest decimal text that reads back to exactly `value`.
std::string format_double(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

const char* attribute_type(int components) {
  switch (components) {
    case 1:
      return "Scalar";
    case 3:
      return "Vector";
    case 6:
      return "Tensor6";
    default:
      throw std::invalid_argument("XDMF attribute with unsupported component count");
  }
}

void append_data_item(std::string& out, const std::string& indent, std::size_t rows, int columns,
                      bool is_int, const std::string& h5_file, const std::string& dataset) {
  out += indent + "<DataItem Dimensions=\"" + std::to_string(rows) + " " + std::to_string(columns) +
         "\" NumberType=\"" + (is_int ? "Int" : "Float") + "\" Precision=\"" +
         (is_int ? "4" : "8") + "\" Format=\"HDF\">" + escape_xml(h5_file + ":" + dataset) +
         "</DataItem>\n";
}

[[noreturn]] void throw_io_error(const std::string& what, const std::filesystem::path& path,
                                 int error) {
  throw std::runtime_error(what + " '" + path.string() + "': " + std::strerror(error));
}

void check_grid(const XdmfPart& grid) {
  if (grid.mixed_connectivity_size == 0 && grid.nodes_per_cell != 3 && grid.nodes_per_cell != 4) {
    throw std::invalid_argument("XDMF part '" + grid.name + "': nodes per cell must be 3 or 4");
  }
}

void append_topology(std::string& out, const XdmfPart& grid, const std::string& h5_file) {
  const bool mixed = grid.mixed_connectivity_size > 0;
  const char* topology = mixed ? "Mixed" : grid.nodes_per_cell == 4 ? "Quadrilateral" : "Triangle";
  out += "        <Topology TopologyType=\"" + std::string(topology) + "\" NumberOfElements=\"" +
         std::to_string(grid.cell_count) + "\">\n";
  if (mixed) {
    out += "          <DataItem Dimensions=\"" + std::to_string(grid.mixed_connectivity_size) +
           "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" +
           escape_xml(h5_file + ":" + grid.connectivity_dataset) + "</DataItem>\n";
  } else {
    append_data_item(out, "          ", grid.cell_count, grid.nodes_per_cell, true, h5_file,
                     grid.connectivity_dataset);
  }
  out += "        </Topology>\n";
}

}  // namespace

std::string make_xdmf(const XdmfPart& part, std::span<const XdmfFrame> frames,
                      const std::string& h5_file) {
  check_grid(part);
  for (const XdmfFrame& frame : frames) {
    if (frame.grid) {
      check_grid(*frame.grid);
    }
  }
  const std::string name = escape_xml(part.name);
  std::string out;
  out += "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n";
  out += "<!-- sheetform results of part '" + name + "': " + std::to_string(frames.size()) +
         " frame(s); heavy data in " + escape_xml(h5_file) + " -->\n";
  out += "<Xdmf Version=\"3.0\">\n  <Domain>\n";
  out += "    <Grid Name=\"" + name + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const XdmfFrame& frame = frames[k];
    const XdmfPart& grid = frame.grid ? *frame.grid : part;
    char index[32];
    std::snprintf(index, sizeof(index), "%06zu", k);
    out += "      <Grid Name=\"" + name + "_" + index + "\" GridType=\"Uniform\">\n";
    out += "        <Time Value=\"" + format_double(frame.time) + "\"/>\n";
    append_topology(out, grid, h5_file);
    out += "        <Geometry GeometryType=\"XYZ\">\n";
    append_data_item(out, "          ", grid.node_count, 3, false, h5_file,
                     frame.coordinates_dataset);
    out += "        </Geometry>\n";
    for (const XdmfAttribute& attribute : frame.attributes) {
      const bool on_nodes = attribute.center == FieldCenter::node;
      out += "        <Attribute Name=\"" + escape_xml(attribute.name) + "\" Center=\"" +
             (on_nodes ? "Node" : "Cell") + "\" AttributeType=\"" +
             attribute_type(attribute.components) + "\">\n";
      append_data_item(out, "          ", on_nodes ? grid.node_count : grid.cell_count,
                       attribute.components, false, h5_file, attribute.dataset);
      out += "        </Attribute>\n";
    }
    out += "      </Grid>\n";
  }
  out += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return out;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view text) {
  std::filesystem::path temporary = path;
  temporary += ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw_io_error("cannot create", temporary, errno);
  }
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n < 0) {
      const int error = errno;
      ::close(fd);
      throw_io_error("cannot write", temporary, error);
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    throw_io_error("cannot flush", temporary, error);
  }
  if (::close(fd) != 0) {
    throw_io_error("cannot close", temporary, errno);
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    throw std::runtime_error("cannot rename '" + temporary.string() + "' to '" + path.string() +
                             "': " + error.message());
  }
}

}  // namespace sf

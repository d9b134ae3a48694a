// A strict reader of the MSH 4.1 binary files gmsh 4.8 writes (gmsh reference manual, "MSH file
// format", version 4.1).
#include "meshing/msh_file.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>

#include "core/errors.hpp"

namespace sf {
namespace {

struct ElementType {
  int type;
  int nodes;
  const char* name;
};

// gmsh's element types up to fifth order (the manual's table), with gmsh's names.
constexpr std::array<ElementType, 33> kElementTypes{{
    {1, 2, "Line 2"},           {2, 3, "Triangle 3"},       {3, 4, "Quadrilateral 4"},
    {4, 4, "Tetrahedron 4"},    {5, 8, "Hexahedron 8"},     {6, 6, "Prism 6"},
    {7, 5, "Pyramid 5"},        {8, 3, "Line 3"},           {9, 6, "Triangle 6"},
    {10, 9, "Quadrilateral 9"}, {11, 10, "Tetrahedron 10"}, {12, 27, "Hexahedron 27"},
    {13, 18, "Prism 18"},       {14, 14, "Pyramid 14"},     {15, 1, "Point"},
    {16, 8, "Quadrilateral 8"}, {17, 20, "Hexahedron 20"},  {18, 15, "Prism 15"},
    {19, 13, "Pyramid 13"},     {20, 9, "Triangle 9"},      {21, 10, "Triangle 10"},
    {22, 12, "Triangle 12"},    {23, 15, "Triangle 15"},    {24, 15, "Triangle 15I"},
    {25, 21, "Triangle 21"},    {26, 4, "Line 4"},          {27, 5, "Line 5"},
    {28, 6, "Line 6"},          {29, 20, "Tetrahedron 20"}, {30, 35, "Tetrahedron 35"},
    {31, 56, "Tetrahedron 56"}, {92, 64, "Hexahedron 64"},  {93, 125, "Hexahedron 125"},
}};

const ElementType* find_type(int type) {
  for (const auto& t : kElementTypes) {
    if (t.type == type) {
      return &t;
    }
  }
  return nullptr;
}

/// Reads the file's bytes front to back; every read checks what is left.
class Cursor {
 public:
  Cursor(std::string_view bytes, const std::filesystem::path& source)
      : bytes_(bytes), source_(source) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(fmt::format(
        "'{}': the mesh gmsh wrote for it cannot be read ({} at byte {}); gmsh 4.8 may have "
        "written it wrongly for this file",
        source_.string(), what, pos_));
  }

  bool at_end() const { return pos_ >= bytes_.size(); }

  /// The text up to the next newline (a trailing '\r' dropped), which it skips.
  std::string_view line() {
    const std::size_t end = bytes_.find('\n', pos_);
    if (end == std::string_view::npos) {
      fail("a line without its end");
    }
    std::string_view text = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (!text.empty() && text.back() == '\r') {
      text.remove_suffix(1);
    }
    return text;
  }

  void expect_line(std::string_view wanted) {
    const std::string_view got = line();
    if (got != wanted) {
      fail(fmt::format("'{}' expected", wanted));
    }
  }

  /// After a binary block gmsh writes a newline, then the section's end.
  void end_section(std::string_view name) {
    if (pos_ < bytes_.size() && bytes_[pos_] == '\n') {
      ++pos_;
    }
    expect_line(fmt::format("$End{}", name));
  }

  template <typename T>
  T read() {
    if (bytes_.size() - pos_ < sizeof(T)) {
      fail("the file ends inside a block");
    }
    T value;
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }

  /// A count of items of at least `item_bytes` each, which must fit in what is left.
  std::size_t count(std::size_t item_bytes) {
    const auto n = read<std::uint64_t>();
    if (n > (bytes_.size() - pos_) / std::max<std::size_t>(item_bytes, 1)) {
      fail(fmt::format("a count of {} larger than the file", n));
    }
    return static_cast<std::size_t>(n);
  }

  /// A positive int (an entity's dimension is checked by the caller).
  int read_int() { return read<std::int32_t>(); }

 private:
  std::string_view bytes_;
  std::filesystem::path source_;
  std::size_t pos_ = 0;
};

struct Entity {
  std::vector<int> physicals;
};
using EntityKey = std::pair<int, int>;  // (dim, tag)

void read_format(Cursor& in) {
  in.expect_line("4.1 1 8");
  if (in.read<std::int32_t>() != 1) {
    in.fail("a byte order other than this machine's");
  }
  in.end_section("MeshFormat");
}

// "dim tag \"name\"" per line, ASCII even in a binary file.
std::map<EntityKey, std::string> read_physical_names(Cursor& in) {
  const std::string count_text(in.line());
  char* end = nullptr;
  const long count = std::strtol(count_text.c_str(), &end, 10);
  if (end == count_text.c_str() || count < 0 || count > 10'000'000) {
    in.fail("a bad count of physical names");
  }
  std::map<EntityKey, std::string> names;
  for (long k = 0; k < count; ++k) {
    const std::string text(in.line());
    int dim = -1, tag = 0, used = 0;
    const std::size_t open = text.find('"'), close = text.rfind('"');
    if (std::sscanf(text.c_str(), "%d %d %n", &dim, &tag, &used) < 2 || dim < 0 || dim > 3 ||
        open == std::string::npos || close <= open) {
      in.fail("a bad physical name line");
    }
    names[{dim, tag}] = text.substr(open + 1, close - open - 1);
  }
  in.expect_line("$EndPhysicalNames");
  return names;
}

void read_int_list(Cursor& in, std::vector<int>* out) {
  const std::size_t n = in.count(sizeof(std::int32_t));
  for (std::size_t k = 0; k < n; ++k) {
    const int value = in.read_int();
    if (out != nullptr) {
      out->push_back(value);
    }
  }
}

std::map<EntityKey, Entity> read_entities(Cursor& in) {
  std::array<std::size_t, 4> counts{};
  for (auto& c : counts) {
    c = in.count(4 + 3 * 8 + 8);  // the smallest entity: a point
  }
  std::map<EntityKey, Entity> entities;
  for (int dim = 0; dim < 4; ++dim) {
    for (std::size_t k = 0; k < counts[static_cast<std::size_t>(dim)]; ++k) {
      const int tag = in.read_int();
      for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) {
        in.read<double>();  // a point's coordinates, or the bounding box
      }
      Entity entity;
      read_int_list(in, &entity.physicals);
      if (dim > 0) {
        read_int_list(in, nullptr);  // bounding entities
      }
      if (!entities.emplace(EntityKey{dim, tag}, std::move(entity)).second) {
        in.fail(fmt::format("entity ({}, {}) given twice", dim, tag));
      }
    }
  }
  in.end_section("Entities");
  return entities;
}

void read_nodes(Cursor& in, GmshModel& model) {
  const std::size_t blocks = in.count(4 * 3 + 8);
  const std::size_t total = in.count(8 + 3 * 8);
  in.read<std::uint64_t>();  // smallest and largest tag: not needed
  in.read<std::uint64_t>();
  model.node_tags.reserve(total);
  std::vector<double> xyz;
  xyz.reserve(3 * total);
  for (std::size_t b = 0; b < blocks; ++b) {
    const int dim = in.read_int();
    in.read_int();  // entity tag
    const int parametric = in.read_int();
    if (dim < 0 || dim > 3 || (parametric != 0 && parametric != 1)) {
      in.fail("a bad node block");
    }
    const std::size_t values = 3 + (parametric == 1 ? static_cast<std::size_t>(dim) : 0);
    const std::size_t n = in.count(8 + values * 8);
    if (model.node_tags.size() + n > total) {
      in.fail("more nodes than the section says");
    }
    const std::size_t first = model.node_tags.size();
    for (std::size_t k = 0; k < n; ++k) {
      const auto tag = in.read<std::uint64_t>();
      if (tag == 0 || !model.node_index.emplace(tag, static_cast<int>(first + k)).second) {
        in.fail(fmt::format("node tag {} is 0 or repeated", tag));
      }
      model.node_tags.push_back(tag);
    }
    for (std::size_t k = 0; k < n; ++k) {
      for (std::size_t v = 0; v < values; ++v) {
        const double value = in.read<double>();
        if (v < 3) {
          xyz.push_back(value);
        }
      }
    }
  }
  if (model.node_tags.size() != total) {
    in.fail("fewer nodes than the section says");
  }
  in.end_section("Nodes");
  model.node_coords = Eigen::Map<const Matrix3X>(xyz.data(), 3, static_cast<Eigen::Index>(total));
}

// Each element block goes to every physical group of its entity, in the file's order.
void read_elements(Cursor& in, const std::map<EntityKey, Entity>& entities,
                   std::map<EntityKey, GmshPhysicalGroup>& groups, const GmshModel& model) {
  const std::size_t blocks = in.count(4 * 3 + 8);
  const std::size_t total = in.count(2 * 8);
  in.read<std::uint64_t>();  // smallest and largest tag
  in.read<std::uint64_t>();
  std::size_t seen = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const int dim = in.read_int();
    const int entity_tag = in.read_int();
    const int type = in.read_int();
    const ElementType* t = find_type(type);
    const auto entity = entities.find({dim, entity_tag});
    if (t == nullptr || entity == entities.end()) {
      in.fail(fmt::format("element type {} or entity ({}, {}) unknown", type, dim, entity_tag));
    }
    const std::size_t per = 1 + static_cast<std::size_t>(t->nodes);
    const std::size_t n = in.count(8 * per);
    seen += n;
    GmshElementBlock block{type, t->name, t->nodes, {}, {}};
    block.element_tags.reserve(n);
    block.node_tags.reserve(n * static_cast<std::size_t>(t->nodes));
    for (std::size_t e = 0; e < n; ++e) {
      block.element_tags.push_back(in.read<std::uint64_t>());
      for (int k = 0; k < t->nodes; ++k) {
        const auto node = in.read<std::uint64_t>();
        if (model.node_index.count(node) == 0) {
          in.fail(fmt::format("element {} names node {}, which has no coordinates",
                              block.element_tags.back(), node));
        }
        block.node_tags.push_back(node);
      }
    }
    for (const int physical : entity->second.physicals) {
      if (physical <= 0) {
        in.fail(fmt::format("physical tag {}", physical));
      }
      GmshPhysicalGroup& group = groups[{dim, physical}];
      auto same = std::find_if(group.elements.begin(), group.elements.end(),
                               [&](const GmshElementBlock& g) { return g.type == type; });
      if (same == group.elements.end()) {
        group.elements.push_back(block);
      } else {
        same->element_tags.insert(same->element_tags.end(), block.element_tags.begin(),
                                  block.element_tags.end());
        same->node_tags.insert(same->node_tags.end(), block.node_tags.begin(),
                               block.node_tags.end());
      }
    }
  }
  if (seen != total) {
    in.fail("an element count other than the section's");
  }
  in.end_section("Elements");
}

// Periodic links (a .geo's Periodic statements): checked for format, not used.
void skip_periodic(Cursor& in) {
  const std::size_t links = in.count(3 * 4 + 2 * 8);
  for (std::size_t k = 0; k < links; ++k) {
    in.read_int();
    in.read_int();
    in.read_int();
    const std::size_t affine = in.count(8);
    for (std::size_t a = 0; a < affine; ++a) {
      in.read<double>();
    }
    const std::size_t pairs = in.count(2 * 8);
    for (std::size_t p = 0; p < 2 * pairs; ++p) {
      in.read<std::uint64_t>();
    }
  }
  in.end_section("Periodic");
}

}  // namespace

int gmsh_nodes_per_element(int type) {
  const ElementType* t = find_type(type);
  return t == nullptr ? 0 : t->nodes;
}

std::string gmsh_type_name(int type) {
  const ElementType* t = find_type(type);
  return t == nullptr ? fmt::format("type {}", type) : std::string(t->name);
}

GmshModel parse_msh41_binary(std::string_view bytes, const std::filesystem::path& source) {
  Cursor in(bytes, source);
  GmshModel model;
  model.file = source;
  std::map<EntityKey, std::string> names;
  std::map<EntityKey, Entity> entities;
  std::map<EntityKey, GmshPhysicalGroup> groups;
  bool format = false, have_entities = false, have_nodes = false, have_elements = false;
  while (!in.at_end()) {
    const std::string_view section = in.line();
    if (section == "$MeshFormat" && !format) {
      read_format(in);
      format = true;
    } else if (!format) {
      in.fail("no $MeshFormat first");
    } else if (section == "$PhysicalNames" && names.empty()) {
      names = read_physical_names(in);
    } else if (section == "$Entities" && !have_entities) {
      entities = read_entities(in);
      have_entities = true;
    } else if (section == "$Nodes" && have_entities && !have_nodes) {
      read_nodes(in, model);
      have_nodes = true;
    } else if (section == "$Elements" && have_nodes && !have_elements) {
      read_elements(in, entities, groups, model);
      have_elements = true;
    } else if (section == "$Periodic" && have_elements) {
      skip_periodic(in);
    } else {
      in.fail(fmt::format("section '{}' not expected here", section.substr(0, 40)));
    }
  }
  if (!have_elements) {
    in.fail("no $Elements section");
  }
  for (auto& [key, group] : groups) {  // std::map: sorted by (dim, tag)
    group.dim = key.first;
    group.tag = key.second;
    const auto name = names.find(key);
    group.name = name == names.end() ? std::string() : name->second;
    for (const auto& block : group.elements) {
      group.node_tags.insert(group.node_tags.end(), block.node_tags.begin(), block.node_tags.end());
    }
    std::sort(group.node_tags.begin(), group.node_tags.end());
    group.node_tags.erase(std::unique(group.node_tags.begin(), group.node_tags.end()),
                          group.node_tags.end());
    model.groups.push_back(std::move(group));
  }
  return model;
}

GmshModel read_msh41_binary(const std::filesystem::path& file, const std::filesystem::path& source,
                            double max_bytes) {
  const auto fail = [&](const std::string& what) {
    return InputError(fmt::format("'{}': the mesh gmsh wrote for it ({}) {}", source.string(),
                                  file.string(), what));
  };
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    throw fail(fmt::format("cannot be opened: {}", std::strerror(errno)));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_nlink != 1 ||
      static_cast<double>(st.st_size) > max_bytes) {
    ::close(fd);
    throw fail("is not a plain file of the size expected");
  }
  std::string bytes(static_cast<std::size_t>(st.st_size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) {
      if (n < 0 && errno == EINTR) {
        continue;
      }
      ::close(fd);
      throw fail("could not be read whole");
    }
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
  return parse_msh41_binary(bytes, source);
}

}  // namespace sf

#include "meshing/file_completeness.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"

namespace sf {
namespace {

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  throw InputError(fmt::format("'{}': {}", file.string(), what));
}

bool is_space(char c) {
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (is_space(text.front()) || text.front() == '\0')) {
    text.remove_prefix(1);
  }
  while (!text.empty() && (is_space(text.back()) || text.back() == '\0')) {
    text.remove_suffix(1);
  }
  return text;
}

std::vector<std::string_view> lines_of(std::string_view bytes) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < bytes.size()) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string_view::npos) {
      end = bytes.size();
    }
    std::string_view line = bytes.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') {
      line.remove_suffix(1);
    }
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

void check_step(const std::filesystem::path& file, std::string_view bytes) {
  std::string_view text = trimmed(bytes);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") {  // a UTF-8 byte-order mark
    text.remove_prefix(3);
  }
  if (text.substr(0, 13) != "ISO-10303-21;") {
    fail(file, "not a STEP file: it does not start with ISO-10303-21;");
  }
  constexpr std::string_view end = "END-ISO-10303-21;";
  if (text.size() < end.size() || text.substr(text.size() - end.size()) != end) {
    fail(file,
         "the STEP file is not whole: it does not end with END-ISO-10303-21; (cut short in a "
         "copy or a download?)");
  }
}

// IGES: fixed records of 80 columns; column 73 holds the section letter (S, G, D, P, T).
void check_iges(const std::filesystem::path& file, std::string_view bytes) {
  std::array<long, 4> counted{};  // S, G, D, P
  constexpr std::string_view letters = "SGDP";
  std::string_view terminate;
  for (const std::string_view line : lines_of(bytes)) {
    if (trimmed(line).empty()) {
      continue;
    }
    if (line.size() < 73) {
      fail(file, fmt::format("not an IGES file, or not whole: a record of {} columns (IGES "
                             "records have 80, the section letter in column 73)",
                             line.size()));
    }
    const char section = line[72];
    const std::size_t k = letters.find(section);
    if (!terminate.empty()) {
      fail(file, "the IGES file has records after its Terminate record");
    }
    if (k != std::string_view::npos) {
      ++counted[k];
    } else if (section == 'T') {
      terminate = line;
    } else {
      fail(file, fmt::format("not an IGES file: section letter '{}' in column 73", section));
    }
  }
  if (terminate.empty()) {
    fail(file,
         "the IGES file is not whole: it has no Terminate record (section T, the last line; cut "
         "short in a copy or a download?)");
  }
  for (std::size_t k = 0; k < 4; ++k) {  // "S      1G      4D     96P     48"
    const std::string field(terminate.substr(8 * k, 8));
    const long stated = field[0] == letters[k] ? std::strtol(field.c_str() + 1, nullptr, 10) : -1;
    if (stated != counted[k]) {
      fail(file, fmt::format("the IGES file is not whole: its Terminate record counts {} {} "
                             "records, the file has {}",
                             stated, letters[k], counted[k]));
    }
  }
}

// ASCII BREP (BRepTools::Write): a "TShapes n" section of n shapes, each closed by its list of
// sub-shapes ending with '*', then the main shape's reference ("+1 0").
void check_brep(const std::filesystem::path& file, std::string_view bytes) {
  const std::vector<std::string_view> lines = lines_of(bytes);
  const auto first = std::find_if(lines.begin(), lines.end(),
                                  [](std::string_view l) { return !trimmed(l).empty(); });
  if (first == lines.end() || (trimmed(*first) != "DBRep_DrawableShape" &&
                               trimmed(*first).substr(0, 16) != "CASCADE Topology")) {
    fail(file,
         "not an OpenCASCADE BREP file (ASCII: it starts with DBRep_DrawableShape or "
         "CASCADE Topology)");
  }
  const auto section = std::find_if(
      lines.begin(), lines.end(), [](std::string_view l) { return l.substr(0, 8) == "TShapes "; });
  if (section == lines.end()) {
    fail(file, "the BREP file is not whole: it has no TShapes section (cut short?)");
  }
  const long shapes = std::strtol(std::string(section->substr(8)).c_str(), nullptr, 10);
  long closed = 0;
  auto it = section + 1;
  for (; it != lines.end() && closed < shapes; ++it) {
    const std::string_view l = trimmed(*it);
    closed += !l.empty() && l.back() == '*' ? 1 : 0;
  }
  const bool has_main =
      std::any_of(it, lines.end(), [](std::string_view l) { return !trimmed(l).empty(); });
  if (closed < shapes || !has_main) {
    fail(file, fmt::format("the BREP file is not whole: its TShapes section announces {} shapes, "
                           "{} are complete{} (cut short in a copy or a download?)",
                           shapes, closed, closed < shapes ? "" : ", the main shape is missing"));
  }
}

// Whitespace-separated words of an ASCII STL, with their line numbers.
class StlWords {
 public:
  explicit StlWords(std::string_view bytes) : bytes_(bytes) {}
  bool next(std::string_view& word) {
    while (pos_ < bytes_.size() && is_space(bytes_[pos_])) {
      line_ += bytes_[pos_++] == '\n' ? 1 : 0;
    }
    const std::size_t start = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) {
      ++pos_;
    }
    word = bytes_.substr(start, pos_ - start);
    return !word.empty();
  }
  int line() const { return line_; }
  bool at_end() const { return pos_ >= bytes_.size(); }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

bool is_number(std::string_view word) {
  const std::string text(word);
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

void check_ascii_stl(const std::filesystem::path& file, std::string_view bytes) {
  StlWords words(bytes);
  std::string_view w;
  long facets = 0;
  const auto cut = [&](const std::string& where) {
    fail(file, fmt::format("the ASCII STL file is not whole: it ends {} (line {}, after {} whole "
                           "triangles; cut short in a copy or a download?)",
                           where, words.line(), facets));
  };
  const auto expect = [&](std::string_view wanted, const char* where) {
    if (!words.next(w) || (w != wanted && words.at_end())) {
      cut(where);  // a last word cut short is a cut too
    }
    if (w != wanted) {
      fail(file, fmt::format("not an ASCII STL file: '{}' where '{}' belongs (line {})",
                             std::string(w.substr(0, 32)), wanted, words.line()));
    }
  };
  bool in_solid = false;
  while (words.next(w)) {
    if (w == "solid") {
      in_solid = true;
    } else if (w == "endsolid") {
      in_solid = false;
    } else if (w == "facet" && in_solid) {
      expect("normal", "inside a facet");
      for (int k = 0; k < 3; ++k) {
        if (!words.next(w)) {
          cut("inside a facet");
        }
      }
      expect("outer", "inside a facet");
      expect("loop", "inside a facet");
      for (int v = 0; v < 3; ++v) {
        expect("vertex", "inside a facet");
        for (int k = 0; k < 3; ++k) {
          if (!words.next(w)) {
            cut("inside a facet");
          }
          if (!is_number(w) && !words.at_end()) {
            fail(file, fmt::format("not an ASCII STL file: '{}' where a coordinate belongs "
                                   "(line {})",
                                   std::string(w.substr(0, 32)), words.line()));
          }
        }
      }
      expect("endloop", "inside a facet");
      expect("endfacet", "inside a facet");
      ++facets;
    }
    // other words: a solid's name after "solid" or "endsolid"
  }
  if (in_solid) {
    cut("before its endsolid");
  }
}

void check_stl(const std::filesystem::path& file, std::string_view bytes) {
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);  // little-endian, as this machine
    if (bytes.size() == 84 + 50 * static_cast<std::uint64_t>(count)) {
      return;  // a whole binary STL
    }
  }
  const std::string_view text = trimmed(bytes);
  const bool printable = std::all_of(bytes.begin(), bytes.end(), [](char c) {
    return is_space(c) || std::isprint(static_cast<unsigned char>(c)) != 0;
  });
  if (text.substr(0, 5) == "solid" && printable) {
    check_ascii_stl(file, bytes);
    return;
  }
  std::uint32_t count = 0;
  if (bytes.size() >= 84) {
    std::memcpy(&count, bytes.data() + 80, 4);
  }
  fail(file, fmt::format("not a whole STL file: as binary STL its header counts {} triangles, "
                         "which take 84 + 50 x {} = {} bytes, and the file has {} (cut short?); "
                         "an ASCII STL is text starting with 'solid'",
                         count, count, 84 + 50 * static_cast<std::uint64_t>(count), bytes.size()));
}

// The first count on the line after `section` ("$Nodes"): MSH 2 gives the count alone, MSH 4 the
// number of blocks first, then the count. -1 when the file has no such section.
double section_count(std::string_view bytes, std::string_view section, bool version4) {
  const std::size_t at = bytes.find(std::string(section) + "\n");
  if (at == std::string_view::npos) {
    return -1.0;
  }
  const std::size_t start = at + section.size() + 1;
  const std::size_t end = bytes.find('\n', start);
  const std::string line(bytes.substr(start, end == std::string_view::npos ? 64 : end - start));
  char* next = nullptr;
  double count = std::strtod(line.c_str(), &next);
  if (version4) {
    count = std::strtod(next, nullptr);
  }
  return count;
}

// A .msh's counts against its size: what a damaged or hostile file claims before gmsh
// allocates for it.
void check_msh(const std::filesystem::path& file, std::string_view bytes) {
  const std::size_t format = bytes.find("$MeshFormat\n");
  if (format == std::string_view::npos) {
    return;  // gmsh says what it makes of it
  }
  const std::string version(bytes.substr(format + 12, 16));
  const bool binary = version.find(" 1 ") != std::string::npos;
  if (binary) {
    return;  // binary counts are checked by gmsh's reader in the sandbox
  }
  const bool version4 = version[0] == '4';
  for (const auto& [section, least_bytes] :
       {std::pair<std::string_view, double>{"$Nodes", 8.0}, {"$Elements", 6.0}}) {
    const double count = section_count(bytes, section, version4);
    if (count * least_bytes > static_cast<double>(bytes.size())) {
      fail(file,
           fmt::format("the file says its {} section holds {:.0f} {}, more than its {} "
                       "bytes can (damaged, or cut short?)",
                       section, count, section == "$Nodes" ? "nodes" : "elements", bytes.size()));
    }
  }
}

}  // namespace

void check_file_is_whole(const std::filesystem::path& file, MeshFormat format,
                         std::string_view bytes) {
  switch (format) {
    case MeshFormat::step:
      check_step(file, bytes);
      break;
    case MeshFormat::iges:
      check_iges(file, bytes);
      break;
    case MeshFormat::brep:
      check_brep(file, bytes);
      break;
    case MeshFormat::stl:
      check_stl(file, bytes);
      break;
    case MeshFormat::msh:
      check_msh(file, bytes);
      break;
    default:
      break;
  }
}

void check_file_is_whole(const std::filesystem::path& file, MeshFormat format) {
  if (format != MeshFormat::step && format != MeshFormat::iges && format != MeshFormat::brep &&
      format != MeshFormat::stl && format != MeshFormat::msh) {
    return;
  }
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in && !in.eof()) {
    fail(file, "cannot be read");
  }
  check_file_is_whole(file, format, bytes.view());
}

}  // namespace sf

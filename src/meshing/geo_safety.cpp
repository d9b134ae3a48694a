#include "meshing/geo_safety.hpp"

#include <fmt/core.h>

#include <cctype>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "meshing/mesh_import.hpp"

namespace sf {

namespace {

// Statements that start a program or end the process.
const std::set<std::string> kRefused = {"SystemCall", "NonBlockingSystemCall", "OnelabRun", "Exit"};

// Include depth beyond which a chain of includes is refused (a file including itself).
constexpr int kMaxIncludeDepth = 16;

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw InputError(fmt::format("'{}': cannot read the file", file.string()));
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Token {
  std::string word;  ///< an identifier, or the text of a string literal (is_string)
  bool is_string = false;
  int line = 1;
};

// Identifiers and string literals, comments skipped (// to the end of the line, /* ... */).
std::vector<Token> tokens(const std::string& text) {
  std::vector<Token> out;
  int line = 1;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') {
        ++i;
      }
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      i += 2;
      while (i + 1 < text.size() && !(text[i] == '*' && text[i + 1] == '/')) {
        line += text[i] == '\n' ? 1 : 0;
        ++i;
      }
      i += 2;
    } else if (c == '"') {
      Token t{"", true, line};
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\' && i + 1 < text.size()) {
          ++i;
        }
        line += text[i] == '\n' ? 1 : 0;
        t.word += text[i];
      }
      ++i;
      out.push_back(std::move(t));
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      Token t{"", false, line};
      while (i < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) {
        t.word += text[i++];
      }
      out.push_back(std::move(t));
    } else {
      ++i;
    }
  }
  return out;
}

void check_file(const std::filesystem::path& file, int depth) {
  if (depth > kMaxIncludeDepth) {
    throw InputError(
        fmt::format("'{}': includes nested deeper than {} files (does a file "
                    "include itself?)",
                    file.string(), kMaxIncludeDepth));
  }
  const std::vector<Token> words = tokens(read_text(file));
  for (std::size_t k = 0; k < words.size(); ++k) {
    const Token& t = words[k];
    if (t.is_string) {
      continue;
    }
    if (kRefused.count(t.word) > 0) {
      throw InputError(fmt::format(
          "'{}', line {}: the statement {} would run a command or end the program; a case file's "
          "geometry must not (give --allow-geo-system-calls to allow it for a file you trust; "
          "docs/case-file.md, Security)",
          file.string(), t.line, t.word));
    }
    if (t.word == "Include" || t.word == "Merge") {
      // Only a literal path can be checked; a computed one (StrCat, ...) could name anything.
      if (k + 1 >= words.size() || !words[k + 1].is_string) {
        throw InputError(fmt::format(
            "'{}', line {}: {} with a computed path cannot be checked for commands; give the "
            "path as a string (or --allow-geo-system-calls for a file you trust)",
            file.string(), t.line, t.word));
      }
      const std::filesystem::path included = file.parent_path() / words[k + 1].word;
      // gmsh parses an Include as a script whatever its name, and a Merge of a file that is not
      // a mesh or CAD format as a script too: those are followed.
      const std::optional<MeshFormat> format = find_mesh_format(included);
      const bool script = t.word == "Include" || !format || *format == MeshFormat::geo;
      // A name the system cannot look up (longer than NAME_MAX: found by fuzzing) is not
      // followed, like a missing file: gmsh cannot read it either, and says so.
      std::error_code unreadable;
      if (script && std::filesystem::is_regular_file(included, unreadable)) {
        check_file(included, depth + 1);
      }
    }
  }
}

}  // namespace

bool& geo_system_calls_allowed() {
  static bool allowed = false;
  return allowed;
}

bool& geo_scan_enabled() {
  static bool enabled = true;
  return enabled;
}

void check_geo_runs_no_commands(const std::filesystem::path& geo_file) {
  if (!geo_system_calls_allowed() && geo_scan_enabled()) {
    check_file(geo_file, 0);
  }
}

}  // namespace sf

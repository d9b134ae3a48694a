#include "solver/case_digest.hpp"

#include <fmt/core.h>

#include <set>
#include <sstream>

namespace sf {

namespace {

class Fnv1a {
 public:
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      h_ = (h_ ^ p[i]) * 1099511628211ull;
    }
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 1469598103934665603ull;
};

// The keys of the resolved case (section, key) a restart may change.
bool may_change(const std::string& section, const std::string& key) {
  static const std::set<std::string> control = {"end_time",          "stroke",
                                                "output_frames",     "history_interval",
                                                "progress_interval", "checkpoint_cycles",
                                                "checkpoint_minutes"};
  return (section == "control" && control.count(key) > 0) ||
         (section == "output" && key == "directory") || key == "mesh";
}

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t");
  const std::size_t b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

std::uint64_t mesh_digest(const Model& model) {
  Fnv1a h;
  auto add_mesh = [&h](const PartMesh& m) {
    h.add(m.nodes.data(), sizeof(double) * static_cast<std::size_t>(m.nodes.size()));
    h.add(m.quads.data(), sizeof(int) * static_cast<std::size_t>(m.quads.size()));
    h.add(m.triangles.data(), sizeof(int) * static_cast<std::size_t>(m.triangles.size()));
  };
  add_mesh(model.blank.mesh);
  for (const Tool& t : model.tools) {
    add_mesh(t.mesh);
  }
  return h.value();
}

std::string case_digest(const Model& model) {
  Fnv1a h;
  std::istringstream text(model.output.resolved_case);
  std::string line, section;
  while (std::getline(text, line)) {
    const std::string item = trim(line);
    if (item.empty() || item[0] == '#') {
      continue;
    }
    if (item[0] == '[') {
      section = item.substr(item.find_first_not_of('['));
      section = section.substr(0, section.find(']'));
    } else if (may_change(section, trim(item.substr(0, item.find('='))))) {
      continue;
    }
    h.add(item.data(), item.size());
    h.add("\n", 1);
  }
  const std::uint64_t meshes = mesh_digest(model);
  h.add(&meshes, sizeof(meshes));
  return fmt::format("{:016x}", h.value());
}

}  // namespace sf

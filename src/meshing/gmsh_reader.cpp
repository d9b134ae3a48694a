// gmsh reader: one gmsh session per call, errors turned into InputError naming the file.
#include "meshing/gmsh_reader.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <omp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmsh.h>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <deque>
#include <exception>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"
#include "core/log.hpp"
#include "meshing/chord_error_size.hpp"
#include "meshing/geo_safety.hpp"
#include "meshing/mesh_import.hpp"

// The sanitizers' hook run before a sanitizer ends the process (libFuzzer sets it to save the
// input as a finding). Weak: null in a build without sanitizers.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace sf {
namespace {

constexpr int gmsh_triangle3 = 2;  // gmsh element type numbers (gmsh reference manual, MSH format)
constexpr int gmsh_quad4 = 3;

std::string quoted(const std::filesystem::path& p) {
  return "'" + p.string() + "'";
}

/// One gmsh session: initialize on construction, finalize on destruction. Restores the OpenMP
/// thread count that gmsh::initialize (and meshing) set to gmsh's own value.
class GmshSession {
 public:
  GmshSession() : saved_threads_(omp_get_max_threads()) {
    try {
      gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);  // no user gmshrc: deterministic
      gmsh::option::setNumber("General.Terminal", verbosity() >= Verbosity::verbose ? 1 : 0);
      gmsh::option::setNumber("General.AbortOnError", 2);  // errors throw instead of going on
      gmsh::option::setNumber("General.NumThreads", 1);    // serial and deterministic
      gmsh::logger::start();
    } catch (...) {
      omp_set_num_threads(saved_threads_);
      throw std::runtime_error("gmsh could not be initialised");
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
  ~GmshSession() {
    try {
      gmsh::logger::stop();
    } catch (...) {
    }
    try {
      gmsh::finalize();
    } catch (...) {
    }
    omp_set_num_threads(saved_threads_);
  }

  /// gmsh's error messages logged so far (lines starting with "Error"), joined by newlines.
  static std::string logged_errors() {
    std::vector<std::string> log;
    try {
      gmsh::logger::get(log);
    } catch (...) {
      return {};
    }
    std::string text;
    auto add = [&text](const std::string& line) { text += (text.empty() ? "" : "\n") + line; };
    for (const auto& line : log) {
      if (line.rfind("Error", 0) == 0) {
        add(line);
      }
      // gmsh only notes a repeated node tag in a .msh and keeps the first node's coordinates:
      // the mesh is not what the file says.
      const std::size_t duplicate = line.find("Skipping duplicate node ");
      if (duplicate != std::string::npos) {
        add("Error: node tag " + line.substr(duplicate + 24) +
            " appears more than once (gmsh keeps the first coordinates and drops the others)");
      }
    }
    return text;
  }

 private:
  int saved_threads_;
};

/// Runs one gmsh step; whatever gmsh throws (std::string, std::exception, anything) or logs as an
/// error becomes an InputError naming the file and the step, with gmsh's messages.
void run_gmsh_step(const std::filesystem::path& file, const std::string& step,
                   const std::function<void()>& body) {
  std::string thrown;
  bool failed = false;
  try {
    body();
  } catch (const InputError&) {
    throw;
  } catch (const std::string& s) {
    failed = true;
    thrown = s;
  } catch (const char* s) {
    failed = true;
    thrown = s ? s : "";
  } catch (const std::exception& e) {
    failed = true;
    thrown = e.what();
  } catch (...) {
    failed = true;
    thrown = "unknown gmsh exception";
  }
  const std::string logged = GmshSession::logged_errors();
  if (!failed && logged.empty()) {
    return;
  }
  std::string message = quoted(file) + ": gmsh failed while " + step;
  if (!logged.empty()) {
    message += ":\n" + logged;
  }
  if (!thrown.empty() && logged.find(thrown) == std::string::npos) {
    message += (logged.empty() ? ": " : "\n") + thrown;
  }
  throw InputError(message);
}

/// Checks what can be checked before gmsh starts: the file exists, its extension, the size.
void check_mesh_source(const std::filesystem::path& file, double element_size,
                       const MeshImportOptions& import) {
  if (!std::filesystem::is_regular_file(file)) {  // gmsh::open does not report a missing file
    throw InputError(quoted(file) + ": mesh file not found");
  }
  const MeshFormat format = mesh_format(file);
  if (!(element_size >= 0.0) || !std::isfinite(element_size)) {
    throw InputError(quoted(file) + ": element size must be >= 0 mm (0 = the file's own sizes)");
  }
  if (is_cad(format) && !(element_size > 0.0)) {
    throw InputError(quoted(file) +
                     ": a CAD file has no mesh sizes of its own: give the part an element_size "
                     "> 0 (mm)");
  }
  if (!(import.scale > 0.0) || !std::isfinite(import.scale)) {
    throw InputError(quoted(file) + ": scale must be > 0");
  }
  if (format == MeshFormat::geo && import.scale != 1.0) {
    throw InputError(quoted(file) +
                     ": a .geo script sets its own lengths: scale is for the other "
                     "formats");
  }
  if (format == MeshFormat::geo) {
    check_geo_runs_no_commands(file);  // before gmsh reads it
  }
}

/// A fresh folder under the system's temporary directory, removed with its content on
/// destruction.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            fmt::format("sheetform-geo-{}-{}", static_cast<long>(::getpid()), counter++);
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out) {
    throw InputError(quoted(file) + ": cannot write this temporary gmsh file");
  }
}

/// The ONELAB number `name`, set by a DefineConstant[ ... Name "name" ] of a parsed .geo.
double read_onelab_number(const std::string& name) {
  std::vector<double> value;
  gmsh::onelab::getNumber(name, value);
  return value.empty() ? std::numeric_limits<double>::quiet_NaN() : value.front();
}

/// Parses `file` as it is and checks that it defines every parameter (gmsh's Exists()).
void check_parameters_defined(const std::filesystem::path& file,
                              std::span<const GeoParameter> parameters,
                              const std::filesystem::path& folder) {
  gmsh::onelab::clear();
  run_gmsh_step(file, "reading the file", [&] { gmsh::open(file.string()); });
  std::string check;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    check += fmt::format(
        "DefineConstant[ sheetform_defined_{0} = {{Exists({1}), Name \"sheetform/defined/{0}\"}} "
        "];\n",
        i, parameters[i].name);
  }
  write_text(folder / "check.geo", check);
  run_gmsh_step(file, "checking its parameters",
                [&] { gmsh::merge((folder / "check.geo").string()); });
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (read_onelab_number(fmt::format("sheetform/defined/{}", i)) != 1.0) {
      throw GeoParameterError(
          i, fmt::format("{} does not define {}: declare it in the file with DefineConstant[ {} = "
                         "<default> ]; (gmsh then takes the value set before the file is parsed)",
                         quoted(file), parameters[i].name, parameters[i].name));
    }
  }
}

/// Opens `file` through a wrapper .geo that assigns the parameters and Includes it, and checks
/// that the file kept every value (a plain assignment in the file would override it).
void open_with_parameters(const std::filesystem::path& file,
                          std::span<const GeoParameter> parameters) {
  const std::string path = std::filesystem::absolute(file).generic_string();
  if (path.find('"') != std::string::npos) {
    throw InputError(quoted(file) + ": a .geo path holding '\"' cannot take parameters");
  }
  const TemporaryFolder folder;
  check_parameters_defined(file, parameters, folder.path());
  std::string wrapper;
  for (const GeoParameter& p : parameters) {
    wrapper += fmt::format("{} = {:.17g};\n", p.name, p.value);
  }
  wrapper += fmt::format("Include \"{}\";\n", path);
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    wrapper += fmt::format(
        "DefineConstant[ sheetform_value_{0} = {{{1}, Name \"sheetform/value/{0}\"}} ];\n", i,
        parameters[i].name);
  }
  const std::filesystem::path wrapper_file = folder.path() / file.filename();
  write_text(wrapper_file, wrapper);
  gmsh::onelab::clear();
  run_gmsh_step(file, "reading the file", [&] { gmsh::open(wrapper_file.string()); });
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const double kept = read_onelab_number(fmt::format("sheetform/value/{}", i));
    if (kept != parameters[i].value) {
      throw GeoParameterError(
          i, fmt::format("{} assigns {} itself ({} = {:g} once the file is read, not the {:g} "
                         "set): declare it with DefineConstant[ {} = {:g} ]; instead of a plain "
                         "assignment, so that it can be set",
                         quoted(file), parameters[i].name, parameters[i].name, kept,
                         parameters[i].value, parameters[i].name, kept));
    }
  }
}

// The message the alarm prints: made before the alarm is armed (the handler may only write).
char g_budget_message[1024];
std::size_t g_budget_message_size = 0;

extern "C" void on_mesh_budget_alarm(int /*signal*/) {
  [[maybe_unused]] const ssize_t written = ::write(2, g_budget_message, g_budget_message_size);
  ::_exit(exit_input_error);
}

// Arms SIGALRM for the budget's seconds while gmsh reads and meshes one file: gmsh has no way to
// be interrupted, so a .geo with a huge loop or an enormous mesh ends the process, said.
class MeshTimeBudget {
 public:
  MeshTimeBudget(const std::filesystem::path& file, double seconds) {
    const std::string text = fmt::format(
        "error: {}: gmsh did not finish reading and meshing it within {:g} s "
        "(limits.mesh_seconds); a loop without end, or far too fine a mesh? Raise "
        "limits.mesh_seconds for a mesh that needs longer\n",
        quoted(file), seconds);
    g_budget_message_size = std::min(text.size(), sizeof(g_budget_message));
    std::copy_n(text.data(), g_budget_message_size, g_budget_message);
    previous_ = std::signal(SIGALRM, on_mesh_budget_alarm);
    ::alarm(static_cast<unsigned>(std::clamp(std::ceil(seconds), 1.0, 1e9)));
  }
  ~MeshTimeBudget() {
    ::alarm(0);
    std::signal(SIGALRM, previous_);
  }
  MeshTimeBudget(const MeshTimeBudget&) = delete;
  MeshTimeBudget& operator=(const MeshTimeBudget&) = delete;

 private:
  void (*previous_)(int) = SIG_DFL;
};

// Refuses a .geo whose element size asks gmsh for more elements than the budget, before gmsh
// tries: the area of each surface is taken as the product of its bounding box's two longest
// sides (exact for a rectangle in a coordinate plane, the right order of size for the others),
// and a triangle of side h covers 0.43 h^2, a quad h^2.
void check_mesh_size_estimate(const std::filesystem::path& file, double element_size,
                              bool recombine) {
  double area = 0.0;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    double lo[3], hi[3];
    gmsh::model::getBoundingBox(dim, tag, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    double sides[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    std::sort(sides, sides + 3);
    area += sides[1] * sides[2];
  }
  const double elements = area / (element_size * element_size) * (recombine ? 1.0 : 2.3);
  if (elements > mesh_budget().max_elements) {
    throw InputError(fmt::format(
        "{}: element_size = {:g} mm asks gmsh for about {:.2g} elements (surfaces of about "
        "{:.4g} mm^2), more than limits.max_elements = {:.3g}; give a larger element_size, or "
        "raise limits.max_elements",
        quoted(file), element_size, elements, area, mesh_budget().max_elements));
  }
}

/// Opens `file` in the current gmsh session; meshes a .geo or CAD file in 2-D; forms the part's
/// group of a CAD or STL file.
void open_and_mesh(const std::filesystem::path& file, double element_size, bool recombine,
                   std::span<const GeoParameter> parameters, const MeshImportOptions& import) {
  const MeshFormat format = mesh_format(file);
  const bool geo = format == MeshFormat::geo;
  if (!geo && !parameters.empty()) {
    throw InputError(quoted(file) +
                     ": parameters are set in a .geo file before gmsh parses it; a .msh file is "
                     "read as it is, and so are the other formats");
  }
  const bool meshed = is_meshed(format);
  const auto set_size = [&] {
    if (meshed && element_size > 0.0) {
      gmsh::option::setNumber("Mesh.MeshSizeMax", element_size);
      gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    }
    if (is_cad(format) && import.curvature_elements > 0) {
      gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", import.curvature_elements);
    }
  };
  run_gmsh_step(file, "setting options", [&] {
    set_size();
    if (is_cad(format)) {
      set_cad_read_options(format, import);
    }
  });
  const MeshTimeBudget budget(file, mesh_budget().seconds);
  if (parameters.empty()) {
    run_gmsh_step(file, "reading the file", [&] { gmsh::open(file.string()); });
  } else {
    open_with_parameters(file, parameters);
  }
  if (meshed && element_size > 0.0) {
    run_gmsh_step(file, "estimating the mesh size",
                  [&] { check_mesh_size_estimate(file, element_size, recombine); });
  }
  if (meshed) {
    run_gmsh_step(file, "meshing in 2-D", [&] {
      set_size();
      if (is_cad(format) && import.chord_error > 0.0) {
        set_chord_error_size(import.chord_error);
      }
      if (recombine) {
        gmsh::option::setNumber("Mesh.RecombineAll", 1);
        // Frontal-Delaunay for quads; gmsh 4.8 crashes with it on a face read from a CAD file
        // (backgroundMesh::getAngle, seen on a plane from STEP), so such faces are meshed with
        // Frontal-Delaunay triangles and recombined.
        gmsh::option::setNumber("Mesh.Algorithm", is_cad(format) ? 6 : 8);
      }
      gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
      gmsh::model::mesh::generate(2);
    });
  }
  if (is_imported(format)) {
    run_gmsh_step(file, "forming the part's group", [&] { group_imported_surfaces(file, import); });
  }
}

/// Copies the current gmsh model into plain data.
GmshModel read_current_model(const std::filesystem::path& file) {
  GmshModel model;
  model.file = file;
  run_gmsh_step(file, "reading the mesh", [&] {
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
    model.node_tags = tags;
    model.node_coords.resize(3, static_cast<Eigen::Index>(tags.size()));
    for (std::size_t i = 0; i < tags.size(); ++i) {
      for (int d = 0; d < 3; ++d) {
        model.node_coords(d, static_cast<Eigen::Index>(i)) = coords[3 * i + d];
      }
      model.node_index.emplace(tags[i], static_cast<int>(i));
    }

    gmsh::vectorpair dim_tags;
    gmsh::model::getPhysicalGroups(dim_tags);
    std::sort(dim_tags.begin(), dim_tags.end());
    for (const auto& [dim, tag] : dim_tags) {
      GmshPhysicalGroup group;
      group.dim = dim;
      group.tag = tag;
      gmsh::model::getPhysicalName(dim, tag, group.name);
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
      std::map<int, std::size_t> block_of_type;
      for (const int entity : entities) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> element_tags, node_tags;
        gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, entity);
        for (std::size_t k = 0; k < types.size(); ++k) {
          auto [it, inserted] = block_of_type.emplace(types[k], group.elements.size());
          if (inserted) {
            GmshElementBlock block;
            block.type = types[k];
            int element_dim = 0, order = 0, primary = 0;
            std::vector<double> local;
            gmsh::model::mesh::getElementProperties(types[k], block.type_name, element_dim, order,
                                                    block.nodes_per_element, local, primary);
            group.elements.push_back(std::move(block));
          }
          GmshElementBlock& block = group.elements[it->second];
          block.element_tags.insert(block.element_tags.end(), element_tags[k].begin(),
                                    element_tags[k].end());
          block.node_tags.insert(block.node_tags.end(), node_tags[k].begin(), node_tags[k].end());
        }
      }
      std::vector<double> group_coords;
      gmsh::model::mesh::getNodesForPhysicalGroup(dim, tag, group.node_tags, group_coords);
      std::sort(group.node_tags.begin(), group.node_tags.end());
      group.node_tags.erase(std::unique(group.node_tags.begin(), group.node_tags.end()),
                            group.node_tags.end());
      model.groups.push_back(std::move(group));
    }
  });

  if (model.node_tags.empty()) {
    throw InputError(quoted(file) + ": the mesh is empty (gmsh made no nodes)");
  }
  if (model.groups.empty()) {
    throw InputError(quoted(file) +
                     ": no physical groups (name the parts, e.g. Physical Surface(\"blank\") = "
                     "{1};)");
  }
  std::size_t element_count = 0;
  for (const auto& group : model.groups) {
    for (const auto& block : group.elements) {
      element_count += block.element_tags.size();
    }
  }
  if (element_count == 0) {
    throw InputError(quoted(file) + ": the mesh is empty (no elements in its physical groups)");
  }
  return model;
}

std::string dim_label(int dim) {
  return std::to_string(dim) + "-D";
}

std::string group_label(const GmshPhysicalGroup& g) {
  return (g.name.empty() ? "(unnamed, tag " + std::to_string(g.tag) + ")" : g.name) + " (" +
         dim_label(g.dim) + ")";
}

/// Orients the elements of `elements` (each a list of 3 or 4 local node indices) consistently
/// over shared edges, per connected piece, keeping the majority orientation. Returns for each
/// element whether it must be reversed.
std::vector<bool> orient_consistently(const std::vector<std::vector<int>>& elements,
                                      const std::vector<std::size_t>& gmsh_tags, const Matrix3X& x,
                                      const std::string& where) {
  // Edge (low, high) -> uses: (element, +1 if the element runs low -> high, else -1).
  std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edges;
  for (int e = 0; e < static_cast<int>(elements.size()); ++e) {
    const auto& el = elements[e];
    const int n = static_cast<int>(el.size());
    for (int k = 0; k < n; ++k) {
      const int a = el[k], b = el[(k + 1) % n];
      edges[{std::min(a, b), std::max(a, b)}].push_back({e, a < b ? 1 : -1});
    }
  }
  const auto edge_text = [&](const std::pair<int, int>& edge) {
    const Vec3 mid = 0.5 * (x.col(edge.first) + x.col(edge.second));
    return fmt::format("edge between gmsh nodes {} and {} (mid-point at ({:.6g}, {:.6g}, {:.6g}))",
                       gmsh_tags[edge.first], gmsh_tags[edge.second], mid(0), mid(1), mid(2));
  };
  struct Neighbour {
    int element;               ///< the other element
    int relation;              ///< sign[element] = relation * sign[this one] when consistent
    std::pair<int, int> edge;  ///< the shared edge, for messages
  };
  std::vector<std::vector<Neighbour>> neighbours(elements.size());
  for (const auto& [edge, uses] : edges) {
    if (uses.size() > 2) {
      throw InputError(where + ": the " + edge_text(edge) + " is shared by " +
                       std::to_string(uses.size()) + " elements (a non-manifold surface)");
    }
    if (uses.size() == 2) {
      // The two elements agree when they run the shared edge in opposite directions.
      const int relation = -uses[0].second * uses[1].second;
      neighbours[uses[0].first].push_back({uses[1].first, relation, edge});
      neighbours[uses[1].first].push_back({uses[0].first, relation, edge});
    }
  }

  std::vector<int> sign(elements.size(), 0);  // +1 keep, -1 reverse, 0 not yet visited
  for (std::size_t seed = 0; seed < elements.size(); ++seed) {
    if (sign[seed] != 0) {
      continue;
    }
    std::vector<int> piece;
    std::deque<int> queue{static_cast<int>(seed)};
    sign[seed] = 1;
    while (!queue.empty()) {
      const int e = queue.front();
      queue.pop_front();
      piece.push_back(e);
      for (const Neighbour& n : neighbours[e]) {
        const int wanted = n.relation * sign[e];
        if (sign[n.element] == 0) {
          sign[n.element] = wanted;
          queue.push_back(n.element);
        } else if (sign[n.element] != wanted) {
          throw InputError(where + ": the surface is not orientable (orientation conflict at the " +
                           edge_text(n.edge) + ")");
        }
      }
    }
    const auto reversed =
        std::count_if(piece.begin(), piece.end(), [&](int e) { return sign[e] < 0; });
    if (2 * static_cast<std::size_t>(reversed) > piece.size()) {  // keep the majority orientation
      for (const int e : piece) {
        sign[e] = -sign[e];
      }
    }
  }
  std::vector<bool> reverse(elements.size());
  for (std::size_t e = 0; e < elements.size(); ++e) {
    reverse[e] = sign[e] < 0;
  }
  return reverse;
}

}  // namespace

const GmshPhysicalGroup* GmshModel::find_group(const std::string& name, int dim) const {
  for (const auto& g : groups) {  // sorted by (dim, tag): the lowest dimension comes first
    if (g.name == name && (dim < 0 || g.dim == dim)) {
      return &g;
    }
  }
  return nullptr;
}

std::string GmshModel::list_groups() const {
  std::string text;
  for (const auto& g : groups) {
    text += (text.empty() ? "" : ", ") + group_label(g);
  }
  return text.empty() ? "none" : text;
}

MeshBudget& mesh_budget() {
  static MeshBudget budget;
  return budget;
}

// The child read's crash is the parent's answer, nothing more: a handler inherited from the
// parent (a fuzzer's, which would save the input as its own finding, or a sanitizer's) must not
// act on it. The child then dies by the signal, or a sanitizer's report exits it with status 1.
void forget_inherited_crash_handlers() {
  if (__sanitizer_set_death_callback != nullptr) {
    __sanitizer_set_death_callback(nullptr);
  }
  for (const int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
    std::signal(signal, SIG_DFL);
  }
}

// gmsh 4.8 (Debian 12) corrupts its heap or reads out of bounds on some malformed .msh files
// (found by fuzzing: tests/fuzz/regressions/mesh_reader): a truncated MSH 4.1 $Nodes block that
// crashes gmsh::finalize, an $Elements block naming a node tag beyond the nodes. A .msh is
// therefore read by gmsh first in a child process (output silenced): a crash there is bad input,
// named, and this process never meets the damage. Costs one more read of the file.
void read_msh_in_child_first(const std::filesystem::path& file) {
  const MeshFormat format = mesh_format(file);
  if (format == MeshFormat::geo || is_cad(format)) {
    return;  // meshed here: a crash would be gmsh's meshing, not the file's syntax
  }
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    return;  // cannot fork: gmsh reads it here, as before
  }
  if (child == 0) {
    forget_inherited_crash_handlers();
    const int null = ::open("/dev/null", O_WRONLY);
    if (null >= 0) {
      ::dup2(null, 1);
      ::dup2(null, 2);
    }
    try {
      GmshSession session;
      gmsh::open(file.string());
      read_current_model(file);  // gmsh's getElements also crashes on a garbled $Entities
    } catch (...) {
      // an error gmsh reports: the read in this process reports it again, as InputError
    }
    ::_exit(0);
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  // The child exits 0 whatever gmsh reported; anything else is a crash (a sanitizer build's
  // child exits 1 after its report instead of dying by the signal).
  if (WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) != 0)) {
    throw InputError(fmt::format(
        "{}: gmsh crashed reading it ({}): the file is damaged, or not a mesh gmsh 4.8 reads; "
        "write it again (`sheetform mesh` writes a .geo's mesh as MSH 4.1)",
        quoted(file),
        WIFSIGNALED(status) ? std::string(strsignal(WTERMSIG(status)))
                            : fmt::format("exit status {}", WEXITSTATUS(status))));
  }
}

GmshModel load_gmsh_model(const std::filesystem::path& file, double element_size, bool recombine,
                          std::span<const GeoParameter> parameters,
                          const MeshImportOptions& import) {
  check_mesh_source(file, element_size, import);
  read_msh_in_child_first(file);
  GmshSession session;
  open_and_mesh(file, element_size, recombine, parameters, import);
  GmshModel model = read_current_model(file);
  if (!is_cad(mesh_format(file))) {
    model.node_coords *= import.scale;  // CAD files are scaled by OpenCASCADE as they are read
  }
  return model;
}

void write_msh(const std::filesystem::path& geo_file, double element_size, bool recombine,
               const std::filesystem::path& msh_out, std::span<const GeoParameter> parameters) {
  check_mesh_source(geo_file, element_size, MeshImportOptions{});
  GmshSession session;
  open_and_mesh(geo_file, element_size, recombine, parameters, MeshImportOptions{});
  read_current_model(geo_file);  // the same checks as load_gmsh_model (empty mesh, no groups)
  run_gmsh_step(msh_out, "writing the mesh", [&] {
    gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    gmsh::option::setNumber("Mesh.Binary", 0);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::write(msh_out.string());
  });
  if (!std::filesystem::is_regular_file(msh_out)) {
    throw InputError(quoted(msh_out) + ": gmsh did not write the mesh file");
  }
}

namespace {

// Whether an element (3 or 4 local node indices) has no area: below 1e-12 of its longest side
// squared (a quad's area from its diagonals' cross product).
bool has_zero_area(const Matrix3X& x, const std::vector<int>& el) {
  auto p = [&](std::size_t k) -> Vec3 { return x.col(el[k]); };
  const std::size_t n = el.size();
  const Vec3 normal =
      n == 4 ? Vec3((p(2) - p(0)).cross(p(3) - p(1))) : Vec3((p(1) - p(0)).cross(p(2) - p(0)));
  double longest = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    longest = std::max(longest, (p((k + 1) % n) - p(k)).squaredNorm());
  }
  return !(0.5 * normal.norm() > 1e-12 * longest);
}

std::string node_tag_list(const std::vector<std::size_t>& tags, const std::vector<int>& el) {
  std::string text;
  for (const int i : el) {
    text += (text.empty() ? "" : " ") + std::to_string(tags[static_cast<std::size_t>(i)]);
  }
  return text;
}

}  // namespace

PartMesh extract_part_mesh(const GmshModel& model, const std::string& group,
                           const std::string& part_name) {
  const std::string where = quoted(model.file) + ", physical group '" + group + "'";
  const GmshPhysicalGroup* g = model.find_group(group, 2);
  if (g == nullptr) {
    const GmshPhysicalGroup* other = model.find_group(group);
    throw InputError(quoted(model.file) + ": no 2-D physical group '" + group + "'" +
                     (other ? " (there is one of dimension " + std::to_string(other->dim) + ")"
                            : std::string()) +
                     "; groups in the file: " + model.list_groups());
  }

  // Local numbering: the group's nodes in ascending gmsh tag order.
  PartMesh part;
  part.name = part_name;
  std::set<std::size_t> tags;
  for (const auto& block : g->elements) {
    if (block.type != gmsh_triangle3 && block.type != gmsh_quad4) {
      throw InputError(where + ": element type '" + block.type_name + "' (gmsh type " +
                       std::to_string(block.type) +
                       ") is not supported; use 4-node quadrangles or 3-node triangles "
                       "(first order, Mesh.ElementOrder = 1)");
    }
    tags.insert(block.node_tags.begin(), block.node_tags.end());
  }
  if (tags.empty()) {
    throw InputError(where + ": the group has no elements");
  }
  part.gmsh_node_tags.assign(tags.begin(), tags.end());
  std::unordered_map<std::size_t, int> local;
  part.nodes.resize(3, static_cast<Eigen::Index>(part.gmsh_node_tags.size()));
  for (std::size_t i = 0; i < part.gmsh_node_tags.size(); ++i) {
    const auto it = model.node_index.find(part.gmsh_node_tags[i]);
    if (it == model.node_index.end()) {
      throw InputError(where + ": element node " + std::to_string(part.gmsh_node_tags[i]) +
                       " has no coordinates");
    }
    part.nodes.col(static_cast<Eigen::Index>(i)) = model.node_coords.col(it->second);
    if (!part.nodes.col(static_cast<Eigen::Index>(i)).allFinite()) {
      throw InputError(fmt::format(
          "{}: node {} has a non-finite coordinate ({}, {}, {})", where, part.gmsh_node_tags[i],
          part.nodes(0, static_cast<Eigen::Index>(i)), part.nodes(1, static_cast<Eigen::Index>(i)),
          part.nodes(2, static_cast<Eigen::Index>(i))));
    }
    local.emplace(part.gmsh_node_tags[i], static_cast<int>(i));
  }

  // All elements, quads first, as local node lists.
  std::vector<std::vector<int>> elements;
  std::vector<std::size_t> element_tags;
  for (const int type : {gmsh_quad4, gmsh_triangle3}) {
    for (const auto& block : g->elements) {
      if (block.type != type) {
        continue;
      }
      const std::size_t n = static_cast<std::size_t>(block.nodes_per_element);
      for (std::size_t e = 0; e < block.element_tags.size(); ++e) {
        std::vector<int> el(n);
        for (std::size_t k = 0; k < n; ++k) {
          el[k] = local.at(block.node_tags[e * n + k]);
        }
        std::vector<int> sorted = el;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
          throw InputError(where + ": element " + std::to_string(block.element_tags[e]) +
                           " is degenerate (a node repeats)");
        }
        elements.push_back(std::move(el));
        element_tags.push_back(block.element_tags[e]);
      }
    }
  }

  const std::vector<bool> reverse =
      orient_consistently(elements, part.gmsh_node_tags, part.nodes, where);
  // After the topology's checks (a Moebius band's closing element can be flat as well).
  for (std::size_t e = 0; e < elements.size(); ++e) {
    if (has_zero_area(part.nodes, elements[e])) {
      throw InputError(fmt::format(
          "{}: element {} has zero area (its nodes, gmsh tags {}, are collinear or coincide)",
          where, element_tags[e], node_tag_list(part.gmsh_node_tags, elements[e])));
    }
  }
  int quad_count = 0, triangle_count = 0;
  for (const auto& el : elements) {
    (el.size() == 4 ? quad_count : triangle_count)++;
  }
  part.quads.resize(4, quad_count);
  part.triangles.resize(3, triangle_count);
  part.reoriented = static_cast<int>(std::count(reverse.begin(), reverse.end(), true));
  int q = 0, t = 0;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    std::vector<int> el = elements[e];
    if (reverse[e]) {
      std::reverse(el.begin() + 1, el.end());  // keeps the first node: (a b c d) -> (a d c b)
    }
    if (el.size() == 4) {
      part.quads.col(q++) << el[0], el[1], el[2], el[3];
    } else {
      part.triangles.col(t++) << el[0], el[1], el[2];
    }
  }
  return part;
}

NodeGroup extract_node_group(const GmshModel& model, const PartMesh& part,
                             const std::string& group) {
  std::vector<std::size_t> tags;
  bool found = false;
  for (const auto& g : model.groups) {
    if (g.name == group) {
      found = true;
      tags.insert(tags.end(), g.node_tags.begin(), g.node_tags.end());
    }
  }
  if (!found) {
    throw InputError(quoted(model.file) + ": no physical group '" + group +
                     "'; groups in the file: " + model.list_groups());
  }
  std::unordered_map<std::size_t, int> local;
  for (std::size_t i = 0; i < part.gmsh_node_tags.size(); ++i) {
    local.emplace(part.gmsh_node_tags[i], static_cast<int>(i));
  }
  NodeGroup result;
  result.name = group;
  for (const std::size_t tag : tags) {
    const auto it = local.find(tag);
    if (it == local.end()) {
      throw InputError(quoted(model.file) + ", physical group '" + group + "': gmsh node " +
                       std::to_string(tag) + " is not a node of part '" + part.name + "'");
    }
    result.nodes.push_back(it->second);
  }
  std::sort(result.nodes.begin(), result.nodes.end());
  result.nodes.erase(std::unique(result.nodes.begin(), result.nodes.end()), result.nodes.end());
  return result;
}

}  // namespace sf

#include "solver/dynain_writer.hpp"

#include <fmt/core.h>

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <span>
#include <vector>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "element/element_block.hpp"
#include "element/shell_output.hpp"
#include "element/shell_surface_strain.hpp"

namespace sf {

std::string keyword_real(double value, int width) {
  const int room = width - 1;  // a blank column before every number, for the eye and for readers
                               // that split at blanks
  if (!std::isfinite(value)) {
    throw InputError(fmt::format("a value of the part is {}, not a number", value));
  }
  std::string best;
  double best_error = INFINITY;
  auto consider = [&](std::string text) {
    if (static_cast<int>(text.size()) > room) {
      return;
    }
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    const double error = std::abs(back - value);
    if (error < best_error) {
      best_error = error;
      best = std::move(text);
    }
  };
  // The fixed form with as many decimals as fit, and the exponent form likewise.
  const int integer_part = static_cast<int>(fmt::format("{:.0f}", value).size());
  if (room - integer_part - 1 >= 1) {
    consider(fmt::format("{:.{}f}", value, room - integer_part - 1));
  }
  for (int digits = room - 6; digits >= 0; --digits) {
    std::string text = fmt::format("{:.{}e}", value, digits);
    if (static_cast<int>(text.size()) <= room) {
      consider(std::move(text));
      break;
    }
  }
  if (best.empty()) {  // |value| beyond e+99 in a narrow field: the closest the width allows
    throw InputError(fmt::format("{} does not fit a field of {} characters", value, width));
  }
  return std::string(static_cast<std::size_t>(width) - best.size(), ' ') + best;
}

namespace {

const std::vector<double>& field(const FormedPart& part, const std::string& key) {
  return part.fields.at(key);
}

// The part's shell state and connectivity, as the element output needs them.
struct PartShell {
  ShellPart shell;
  ShellState state;
  Matrix3X x;
};

PartShell part_shell(const FormedPart& part) {
  PartShell p;
  p.shell.quads = part.quads;
  p.shell.triangles = part.triangles;
  const auto rule = find_choice<ThroughThicknessRule>(kThroughThicknessRuleNames, part.rule);
  if (!rule) {
    throw InputError(
        fmt::format("{}: /section@rule is \"{}\", not gauss or lobatto", part.file, part.rule));
  }
  p.shell.section = make_section(part.n_points, *rule);
  p.state.n_elements = element_count(p.shell);
  p.state.n_points = part.n_points;
  p.state.sxx = field(part, "shell/sxx");
  p.state.syy = field(part, "shell/syy");
  p.state.sxy = field(part, "shell/sxy");
  p.state.sxz = field(part, "shell/sxz");
  p.state.syz = field(part, "shell/syz");
  p.state.eps_p = field(part, "shell/eps_p");
  p.state.thickness = field(part, "shell/thickness");
  const std::vector<double>& x = field(part, "x");
  const auto n = part.reference_nodes.cols();
  const auto per_point = static_cast<std::size_t>(p.state.n_elements * p.state.n_points);
  const auto per_element = static_cast<std::size_t>(p.state.n_elements);
  if (x.size() != static_cast<std::size_t>(3 * n) || p.state.sxx.size() != per_point ||
      p.state.syy.size() != per_point || p.state.sxy.size() != per_point ||
      p.state.eps_p.size() != per_point || p.state.sxz.size() != per_element ||
      p.state.syz.size() != per_element || p.state.thickness.size() != per_element) {
    throw InputError(fmt::format("{}: the state's sizes do not fit its mesh", part.file));
  }
  p.x = Eigen::Map<const Matrix3X>(x.data(), 3, n);
  return p;
}

// The element's node numbers (1-based), a triangle's third repeated as the fourth.
std::array<int, 4> element_nodes(const PartShell& p, int e) {
  const ElementBlock block = block_of(p.shell, e);
  const int* n = block.element_nodes(e);
  const int last = n[block.nodes_per_element() - 1];
  return {n[0] + 1, n[1] + 1, n[2] + 1, last + 1};
}

void write_nodes(std::ostream& out, const PartShell& p) {
  out << "*NODE\n$#   nid               x               y               z      tc      rc\n";
  for (Eigen::Index i = 0; i < p.x.cols(); ++i) {
    out << fmt::format("{:>8}{}{}{}{:>8}{:>8}\n", i + 1, keyword_real(p.x(0, i), 16),
                       keyword_real(p.x(1, i), 16), keyword_real(p.x(2, i), 16), 0, 0);
  }
}

// The element's part id: 1, or for a blank of several parts its part's index plus one.
int part_id(const FormedPart& part, int e) {
  return part.element_part.empty() ? 1 : part.element_part[static_cast<std::size_t>(e)] + 1;
}

// The header's lines naming the parts (each on its own line, within the 80 columns).
std::string parts_comment(const FormedPart& part) {
  if (part.part_names.empty()) {
    return "$ Part 1";
  }
  std::string text = "$ Parts by pid:";
  for (std::size_t p = 0; p < part.part_names.size(); ++p) {
    text += fmt::format("\n$   {} = {}", p + 1, part.part_names[p]);
  }
  return text + "\n$ Parts";
}

void write_elements(std::ostream& out, const FormedPart& part, const PartShell& p) {
  out << "*ELEMENT_SHELL_THICKNESS\n"
         "$#   eid     pid      n1      n2      n3      n4      n5      n6      n7      n8\n"
         "$#         thic1           thic2           thic3           thic4            beta\n";
  for (int e = 0; e < p.state.n_elements; ++e) {
    const std::array<int, 4> n = element_nodes(p, e);
    out << fmt::format("{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}\n", e + 1,
                       part_id(part, e), n[0], n[1], n[2], n[3], 0, 0, 0, 0);
    const std::string t = keyword_real(p.state.thickness[static_cast<std::size_t>(e)], 16);
    out << t << t << t << t << keyword_real(0.0, 16) << '\n';
  }
}

// The total strains of the bottom and top surfaces, from the reference and current shape
// (element/shell_surface_strain.hpp).
void write_strains(std::ostream& out, const FormedPart& part, const PartShell& p) {
  out << "*INITIAL_STRAIN_SHELL\n"
         "$#     eid    nplane    nthick     large\n"
         "$#   epsxx     epsyy     epszz     epsxy     epsyz     epszx         t\n";
  const Matrix3X normal0 =
      nodal_unit_normals(p.shell.quads, p.shell.triangles, part.reference_nodes);
  const Matrix3X normal = nodal_unit_normals(p.shell.quads, p.shell.triangles, p.x);
  std::array<Vec3, 4> X, x, N, n;
  for (int e = 0; e < p.state.n_elements; ++e) {
    const std::array<int, 4> nodes = element_nodes(p, e);
    const auto corners = static_cast<std::size_t>(block_of(p.shell, e).nodes_per_element());
    for (std::size_t a = 0; a < corners; ++a) {
      const int i = nodes[a] - 1;
      X[a] = part.reference_nodes.col(i);
      x[a] = p.x.col(i);
      N[a] = normal0.col(i);
      n[a] = normal.col(i);
    }
    const ElementCorners c{
        {X.data(), corners}, {x.data(), corners}, {N.data(), corners}, {n.data(), corners}};
    const auto ue = static_cast<std::size_t>(e);
    out << fmt::format("{:>10}{:>10}{:>10}{:>10}\n", e + 1, 1, 2, 0);
    for (double zeta : {-1.0, 1.0}) {
      const Strain6 s =
          surface_log_strain(c, zeta, part.initial_thickness[ue], p.state.thickness[ue]);
      for (int k = 0; k < 6; ++k) {
        out << keyword_real(s[k], 10);
      }
      out << keyword_real(zeta, 10) << '\n';
    }
  }
}

void write_stresses(std::ostream& out, const PartShell& p) {
  out << "*INITIAL_STRESS_SHELL\n"
         "$#     eid    nplane    nthick     nhisv    ntensr     large    nthint    nthhsv\n"
         "$#       t     sigxx     sigyy     sigzz     sigxy     sigyz     sigzx       eps\n";
  std::vector<Stress6> stress(static_cast<std::size_t>(p.state.n_points));
  for (int e = 0; e < p.state.n_elements; ++e) {
    compute_point_stresses(p.shell, p.x, p.state, e, stress);
    out << fmt::format("{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}{:>10}\n", e + 1, 1,
                       p.state.n_points, 0, 0, 0, 0, 0);
    for (int k = 0; k < p.state.n_points; ++k) {
      const Stress6& s = stress[static_cast<std::size_t>(k)];  // xx, yy, zz, xy, yz, xz
      const auto i = static_cast<std::size_t>(e * p.state.n_points + k);
      out << keyword_real(p.shell.section.zeta[static_cast<std::size_t>(k)], 10)
          << keyword_real(s[0], 10) << keyword_real(s[1], 10) << keyword_real(s[2], 10)
          << keyword_real(s[3], 10) << keyword_real(s[4], 10) << keyword_real(s[5], 10)
          << keyword_real(p.state.eps_p[i], 10) << '\n';
    }
  }
}

}  // namespace

void write_dynain(const FormedPart& part, const std::filesystem::path& file) {
  const PartShell p = part_shell(part);
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  {
    std::ofstream out(temporary);
    out << "*KEYWORD\n"
        << "$ sheetform " << build_info::version << " (" << build_info::git_hash
        << "): the formed part " << part.file << " at t = " << field(part, "time").front() << " s\n"
        << "$ units: mm, tonne, s; N, MPa (stresses in global components, every through-\n"
        << "$ thickness point: t = its position from -1 bottom to +1 top; eps = equivalent\n"
        << "$ plastic strain). *INITIAL_STRAIN_SHELL: logarithmic strains of the bottom\n"
        << "$ (t = -1) and top (t = +1) surfaces, global tensor components (epsxy is half\n"
        << "$ the engineering shear), measured from the reference and current shape.\n"
        << parts_comment(part) << "; material axes not written (beta = 0).\n";
    write_nodes(out, p);
    write_elements(out, part, p);
    write_stresses(out, p);
    write_strains(out, part, p);
    out << "*END\n";
    out.close();
    if (!out) {
      throw OutputError(fmt::format("cannot write the dynain file {}", file.string()));
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) {
    throw OutputError(
        fmt::format("cannot write the dynain file {}: {}", file.string(), error.message()));
  }
}

}  // namespace sf

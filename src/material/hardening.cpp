#include "material/hardening.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include "core/errors.hpp"

namespace sf {

double SwiftHardening::flow_stress(double eps_p) const {
  return K * std::pow(eps0 + eps_p, n);
}

double SwiftHardening::slope(double eps_p) const {
  return n == 0.0 ? 0.0 : n * K * std::pow(eps0 + eps_p, n - 1.0);
}

FlowStress VoceHardening::evaluate(double eps_p) const {
  const double x = Q * std::exp(-b * eps_p);
  return {sigma0 + Q - x, b * x};
}

FlowStress LudwikHardening::evaluate(double eps_p) const {
  if (!(eps_p > 0.0)) {
    const double slope = n < 1.0 ? std::numeric_limits<double>::infinity() : (n == 1.0 ? B : 0.0);
    return {A, B == 0.0 ? 0.0 : slope};
  }
  const double hardening = B * std::pow(eps_p, n);
  return {A + hardening, n * hardening / eps_p};
}

FlowStress HockettSherbyHardening::evaluate(double eps_p) const {
  const double range = sigma_s - sigma_i;
  if (!(eps_p > 0.0)) {
    const double slope = p < 1.0 ? std::numeric_limits<double>::infinity() : range * N;
    return {sigma_i, range == 0.0 ? 0.0 : slope};
  }
  const double power = p == 1.0 ? eps_p : std::pow(eps_p, p);
  const double decay = range * std::exp(-N * power);
  return {sigma_s - decay, decay * N * p * power / eps_p};
}

FlowStress TabulatedHardening::evaluate(double e) const {
  const std::size_t n = eps_p.size();
  if (n < 2) {
    return {stress.empty() ? 0.0 : stress[0], 0.0};
  }
  // Segment [i, i + 1] holding e: the first point strictly above e, minus one, clamped to a
  // valid segment (extrapolation below 0 and above the last point uses the end segments).
  const auto it = std::upper_bound(eps_p.begin(), eps_p.end(), e);
  std::size_t i = static_cast<std::size_t>(it - eps_p.begin());
  i = std::clamp<std::size_t>(i, 1, n - 1) - 1;
  const double slope = (stress[i + 1] - stress[i]) / (eps_p[i + 1] - eps_p[i]);
  return {stress[i] + slope * (e - eps_p[i]), slope};
}

double flow_stress(const Hardening& hardening, double eps_p) {
  return std::visit([eps_p](const auto& h) { return h.flow_stress(eps_p); }, hardening);
}

double hardening_slope(const Hardening& hardening, double eps_p) {
  return std::visit([eps_p](const auto& h) { return h.slope(eps_p); }, hardening);
}

namespace {

std::string num(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

// Empty string when the table is valid, otherwise what is wrong, naming the 1-based row.
std::string table_error(const std::vector<double>& e, const std::vector<double>& s,
                        const std::vector<int>* lines) {
  const auto row = [lines](std::size_t i) {
    return lines ? "line " + std::to_string((*lines)[i]) : "row " + std::to_string(i + 1);
  };
  if (e.size() != s.size()) {
    return "tabulated hardening needs as many strains as stresses (got " +
           std::to_string(e.size()) + " and " + std::to_string(s.size()) + ")";
  }
  if (e.empty()) {
    return "tabulated hardening needs at least one point";
  }
  for (std::size_t i = 0; i < e.size(); ++i) {
    if (!std::isfinite(e[i]) || !std::isfinite(s[i])) {
      return row(i) + ": tabulated hardening values must be finite";
    }
    if (!(s[i] > 0.0)) {
      return row(i) + ": tabulated flow stress must be > 0 (got " + num(s[i]) + ")";
    }
    if (i == 0 && e[0] != 0.0) {
      return row(i) + ": tabulated hardening must start at plastic strain 0 (got " + num(e[0]) +
             ")";
    }
    if (i > 0 && !(e[i] > e[i - 1])) {
      return row(i) + ": plastic strain must increase strictly (" + num(e[i]) + " after " +
             num(e[i - 1]) + ")";
    }
    if (i > 0 && s[i] < s[i - 1]) {
      return row(i) + ": flow stress must not decrease (" + num(s[i]) + " after " + num(s[i - 1]) +
             ")";
    }
  }
  return {};
}

bool all_finite(std::initializer_list<double> xs) {
  return std::all_of(xs.begin(), xs.end(), [](double x) { return std::isfinite(x); });
}

}  // namespace

void check_hardening(const Hardening& hardening, const char* what) {
  const std::string name(what);
  if (const auto* s = std::get_if<SwiftHardening>(&hardening)) {
    if (!(s->K > 0.0) || !(s->eps0 > 0.0) || !(s->n >= 0.0) || !all_finite({s->K, s->eps0, s->n})) {
      throw InputError(name + ": Swift hardening needs K > 0, eps0 > 0 and n >= 0 (got K = " +
                       num(s->K) + ", eps0 = " + num(s->eps0) + ", n = " + num(s->n) + ")");
    }
  } else if (const auto* l = std::get_if<LinearHardening>(&hardening)) {
    if (!(l->sigma_y0 > 0.0) || !(l->H >= 0.0) || !all_finite({l->sigma_y0, l->H})) {
      throw InputError(name + ": linear hardening needs yield stress > 0 and modulus >= 0 (got " +
                       num(l->sigma_y0) + ", " + num(l->H) + ")");
    }
  } else if (const auto* v = std::get_if<VoceHardening>(&hardening)) {
    if (!(v->sigma0 > 0.0) || !(v->Q >= 0.0) || !(v->b > 0.0) ||
        !all_finite({v->sigma0, v->Q, v->b})) {
      throw InputError(name + ": Voce hardening needs sigma0 > 0, Q >= 0 and b > 0 (got " +
                       num(v->sigma0) + ", " + num(v->Q) + ", " + num(v->b) + ")");
    }
  } else if (const auto* h = std::get_if<LudwikHardening>(&hardening)) {
    if (!(h->A > 0.0) || !(h->B >= 0.0) || !(h->n > 0.0 && h->n <= 1.0) ||
        !all_finite({h->A, h->B, h->n})) {
      throw InputError(name + ": Ludwik hardening needs A > 0, B >= 0 and 0 < n <= 1 (got A = " +
                       num(h->A) + ", B = " + num(h->B) + ", n = " + num(h->n) + ")");
    }
  } else if (const auto* hs = std::get_if<HockettSherbyHardening>(&hardening)) {
    if (!(hs->sigma_i > 0.0) || !(hs->sigma_s >= hs->sigma_i) || !(hs->N > 0.0) ||
        !(hs->p > 0.0 && hs->p <= 1.0) || !all_finite({hs->sigma_s, hs->sigma_i, hs->N, hs->p})) {
      throw InputError(name +
                       ": Hockett-Sherby hardening needs sigma_s >= sigma_i > 0, N > 0 and "
                       "0 < p <= 1 (got sigma_s = " +
                       num(hs->sigma_s) + ", sigma_i = " + num(hs->sigma_i) +
                       ", N = " + num(hs->N) + ", p = " + num(hs->p) + ")");
    }
  } else if (const auto* sv = std::get_if<SwiftVoceHardening>(&hardening)) {
    if (!(sv->weight >= 0.0 && sv->weight <= 1.0)) {
      throw InputError(name + ": Swift-Voce hardening needs 0 <= weight <= 1 (got " +
                       num(sv->weight) + ")");
    }
    check_hardening(sv->swift, what);
    check_hardening(sv->voce, what);
  } else {
    const auto& t = std::get<TabulatedHardening>(hardening);
    const std::string err = table_error(t.eps_p, t.stress, nullptr);
    if (!err.empty()) {
      throw InputError(name + ": " + err);
    }
  }
}

TabulatedHardening read_hardening_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) {
    throw InputError(path.string() + ": cannot open hardening table");
  }
  TabulatedHardening t;
  std::vector<int> lines;
  bool header_allowed = true;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) {
      line.erase(hash);
    }
    for (char& c : line) {
      if (c == ',' || c == ';' || c == '\t' || c == '\r') {
        c = ' ';
      }
    }
    double v[2];
    int count = 0;
    bool bad = false;
    const char* p = line.data();
    const char* end = p + line.size();
    while (true) {
      while (p < end && *p == ' ') {
        ++p;
      }
      if (p == end) {
        break;
      }
      double x = 0.0;
      const auto r = std::from_chars(p, end, x);
      if (r.ec != std::errc() || (r.ptr < end && *r.ptr != ' ') || count == 2) {
        bad = true;
        break;
      }
      v[count++] = x;
      p = r.ptr;
    }
    if (!bad && count == 0) {
      continue;  // blank or comment line
    }
    if (bad || count != 2) {
      if (header_allowed && bad) {
        header_allowed = false;  // the one optional header line
        continue;
      }
      throw InputError(path.string() + ": line " + std::to_string(number) +
                       ": expected two numbers (plastic strain, true stress MPa), got '" + line +
                       "'");
    }
    header_allowed = false;
    t.eps_p.push_back(v[0]);
    t.stress.push_back(v[1]);
    lines.push_back(number);
  }
  const std::string err = table_error(t.eps_p, t.stress, &lines);
  if (!err.empty()) {
    throw InputError(path.string() + ": " + err);
  }
  return t;
}

}  // namespace sf

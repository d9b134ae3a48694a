#include "solver/implicit_summary.hpp"

#include <fmt/core.h>

#include <cmath>

namespace sf {

namespace {

std::string iteration_list(const StaticStepReport& r) {
  std::string list;
  for (const IncrementRecord& inc : r.increments) {
    if (inc.converged) {
      list += fmt::format("{}{}", list.empty() ? "" : " ", inc.iterations.size());
    }
  }
  return list;
}

nlohmann::json rho_json(double rho) {
  return std::isfinite(rho) ? nlohmann::json(rho) : nlohmann::json(nullptr);
}

nlohmann::json u_channel_json(const UChannelMeasures& m) {
  return {{"theta1_deg", m.theta1},     {"theta2_deg", m.theta2},
          {"rho_mm", rho_json(m.rho)},  {"bottom_nodes", m.bottom_nodes},
          {"wall_nodes", m.wall_nodes}, {"flange_nodes", m.flange_nodes}};
}

std::string format_rho(double rho) {
  return std::isfinite(rho) ? fmt::format("{:.1f} mm", rho) : std::string("infinite (straight)");
}

}  // namespace

std::string format_implicit_step(const ImplicitStepSummary& step) {
  const StaticStepReport& r = step.report;
  const FactorizationStats& f = r.last_factorization;
  std::string text;
  auto add = [&text](const std::string& line) { text += line + "\n"; };
  const int solved = r.converged_increments + r.settling_increments;
  add(fmt::format(
      "  increments          {} converged{}, {} cut; Newton iterations {} ({} per "
      "increment: {})",
      r.converged_increments,
      r.settling_increments > 0
          ? fmt::format(" + {} settling at load factor 1 (stabilised)", r.settling_increments)
          : std::string(),
      r.cuts, r.newton_iterations,
      solved > 0 ? fmt::format("{:.1f}", static_cast<double>(r.newton_iterations) / solved)
                 : std::string("-"),
      iteration_list(r)));
  add(fmt::format("  final residual      {:.2e} (relative to the reference force)",
                  r.final_residual));
  add(
      fmt::format("  linear solver       {} ({} CHOLMOD, {} UMFPACK factorisations; tangent "
                  "asymmetry up to {:.1e})",
                  method_name(f.method), r.solver.cholmod_factorizations,
                  r.solver.umfpack_factorizations, r.solver.max_asymmetry));
  add(fmt::format(
      "  matrix              {} equations, {} nonzeros; factor {} nonzeros, fill {:.2f}",
      r.equations, f.matrix_nonzeros, f.factor_nonzeros, f.fill_ratio));
  add(
      fmt::format("  times               tangent {:.3f} s ({} colours, {} force evaluations), "
                  "analysis {:.3f} s, factorisation {:.3f} s, solves {:.3f} s; step {:.2f} s",
                  r.tangent_seconds, r.colours, r.tangent_evaluations, r.solver.analyse_seconds,
                  r.solver.factor_seconds, r.solver.solve_seconds, step.wall_seconds));
  if (r.prescribed_work != 0.0) {
    add(fmt::format(
        "  prescribed motion   work {:.6g} N mm (part of the external work {:.6g} N mm)",
        r.prescribed_work, r.external_work));
  }
  for (const std::string& held : step.added_constraints) {
    add(fmt::format("  rigid-body hold     {}", held));
  }
  return text;
}

std::string format_springback(const SpringbackSummary& s) {
  std::string text;
  auto add = [&text](const std::string& line) { text += line + "\n"; };
  add(fmt::format("Springback ({})", s.method));
  if (s.implicit) {
    text += format_implicit_step(*s.implicit);
  }
  if (s.relaxation) {
    const DynamicRelaxationResult& d = *s.relaxation;
    add(
        fmt::format("  release             {:.4e} s, then relaxation {:.4e} s, {} cycles; kinetic "
                    "/ internal {:.2e} at the end ({})",
                    d.release_time, d.relaxation_time, d.cycles, d.final_kinetic_ratio,
                    d.at_rest ? "at rest" : "NOT at rest: max_time reached"));
  }
  add(fmt::format("  displacement        {:.4f} mm at most (node {}); wall time {:.2f} s",
                  s.max_displacement, s.max_displacement_node, s.wall_seconds));
  if (s.u_channel && s.u_channel_formed) {
    const UChannelMeasures& a = *s.u_channel_formed;
    const UChannelMeasures& b = *s.u_channel;
    add(
        fmt::format("  U-channel           theta1 {:.2f} deg, theta2 {:.2f} deg, rho {} (formed: "
                    "{:.2f}, {:.2f}, {})",
                    b.theta1, b.theta2, format_rho(b.rho), a.theta1, a.theta2, format_rho(a.rho)));
  }
  return text;
}

nlohmann::json implicit_step_json(const ImplicitStepSummary& step) {
  const StaticStepReport& r = step.report;
  const FactorizationStats& f = r.last_factorization;
  nlohmann::json iterations = nlohmann::json::array();
  nlohmann::json increments = nlohmann::json::array();
  for (const IncrementRecord& inc : r.increments) {
    nlohmann::json residuals = nlohmann::json::array();
    for (const NewtonIteration& it : inc.iterations) {
      residuals.push_back(it.residual);
    }
    increments.push_back({{"lambda_start", inc.lambda_start},
                          {"lambda_end", inc.lambda_end},
                          {"converged", inc.converged},
                          {"initial_residual", inc.initial_residual},
                          {"residuals", residuals},
                          {"stabilization_N_per_mm", inc.stabilization},
                          {"unbalanced", inc.unbalanced},
                          {"failure", inc.failure}});
    if (inc.converged) {
      iterations.push_back(inc.iterations.size());
    }
  }
  return {{"converged_increments", r.converged_increments},
          {"settling_increments", r.settling_increments},
          {"cuts", r.cuts},
          {"newton_iterations", r.newton_iterations},
          {"iterations_per_increment", iterations},
          {"increments", increments},
          {"final_residual", r.final_residual},
          {"linear_solver", method_name(f.method)},
          {"cholmod_factorizations", r.solver.cholmod_factorizations},
          {"umfpack_factorizations", r.solver.umfpack_factorizations},
          {"max_tangent_asymmetry", r.solver.max_asymmetry},
          {"equations", r.equations},
          {"matrix_nonzeros", f.matrix_nonzeros},
          {"factor_nonzeros", f.factor_nonzeros},
          {"fill_ratio", f.fill_ratio},
          {"colours", r.colours},
          {"tangent_evaluations", r.tangent_evaluations},
          {"tangent_seconds", r.tangent_seconds},
          {"analyse_seconds", r.solver.analyse_seconds},
          {"factor_seconds", r.solver.factor_seconds},
          {"solve_seconds", r.solver.solve_seconds},
          {"wall_seconds", step.wall_seconds},
          {"internal_work_Nmm", r.internal_work},
          {"hourglass_work_Nmm", r.hourglass_work},
          {"external_work_Nmm", r.external_work},
          {"prescribed_work_Nmm", r.prescribed_work},
          {"free_rigid_body_modes", step.free_modes},
          {"added_constraints", step.added_constraints}};
}

nlohmann::json springback_json(const SpringbackSummary& s) {
  nlohmann::json j = {{"method", s.method},
                      {"wall_seconds", s.wall_seconds},
                      {"max_displacement_mm", s.max_displacement},
                      {"max_displacement_node", s.max_displacement_node}};
  if (s.implicit) {
    j["implicit"] = implicit_step_json(*s.implicit);
  }
  if (s.relaxation) {
    const DynamicRelaxationResult& d = *s.relaxation;
    j["dynamic_relaxation"] = {{"release_time_s", d.release_time},
                               {"relaxation_time_s", d.relaxation_time},
                               {"cycles", d.cycles},
                               {"final_kinetic_ratio", d.final_kinetic_ratio},
                               {"at_rest", d.at_rest}};
  }
  if (s.u_channel) {
    j["u_channel"] = u_channel_json(*s.u_channel);
  }
  if (s.u_channel_formed) {
    j["u_channel_formed"] = u_channel_json(*s.u_channel_formed);
  }
  return j;
}

}  // namespace sf

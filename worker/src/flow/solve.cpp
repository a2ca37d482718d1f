// SPDX-License-Identifier: GPL-3.0-or-later
// The solve pipeline of one job (solve.h), with timing and memory figures.
#include "flow/solve.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <cmath>
#include <spdlog/spdlog.h>

#include "coupling/drag_field.h"
#include "coupling/solids_fraction.h"
#include "flow/checkpoint.h"
#include "flow/initial_state.h"
#include "flow/fas_coarse_level.h"
#include "flow/mass_flux.h"
#include "flow/newton_outer.h"
#include "flow/probes.h"
#include "flow/prolong.h"
#include "flow/vtk_writer.h"
#include "job/job_hash.h"

namespace gridfree {
namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec) + double(u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_stime.tv_usec);
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A solution on a coarser grid: the nested start of a finer one, used only
// when `usable`.
struct CoarseSolution {
  Grid grid;
  CellField p;
  FaceVector u;
  bool usable = false;
  nlohmann::json levels = nlohmann::json::array();  // what each coarser solve did, coarsest first
};

// The grid of the nested start: every axis with at least kMinAxisCells
// cells halved (rounded), none when the fine grid has fewer than
// `min_cells` cells (docs/SOLVER.md, "Nested start").
constexpr int kMinAxisCells = 4;
std::optional<std::array<int, 3>> coarser_cells(const std::array<int, 3>& n, std::size_t min_cells) {
  const std::size_t cells = std::size_t(n[0]) * n[1] * n[2];
  if (cells < min_cells) return std::nullopt;
  std::array<int, 3> c = n;
  for (int a = 0; a < 3; ++a)
    if (n[a] >= kMinAxisCells) c[a] = (n[a] + 1) / 2;
  return c;
}

JobResult solve_grid(const JobSpec& job, const ParticleSet& particles, const SolveOptions& options,
                     CoarseSolution* keep);

// A coarse level starts the grid above when it converged, or when it
// stopped (stalled, or at the cap) with both residuals within
// kUsableStartFactor × the steady tolerance: a limit cycle just above the
// tolerance is still a close start (docs/SOLVER.md "Nested start").
constexpr double kUsableStartFactor = 10;
bool usable_start(const JobResult& r, double steady_tolerance) {
  if (r.status == SolveStatus::kConverged) return true;
  const double worst = std::max(r.residual_continuity, r.residual_momentum);
  return r.status == SolveStatus::kNotConverged && std::isfinite(worst) &&
         worst <= kUsableStartFactor * steady_tolerance;
}

// Solves the job on the coarser grid (itself started the same way), at
// most options.nested_max_iterations outer iterations; nullopt when the
// grid has no coarser level. The levels are reported whether or not the
// coarse solve converged.
std::optional<CoarseSolution> nested_start(const JobSpec& job, const ParticleSet& particles,
                                           const SolveOptions& options) {
  const auto cells = coarser_cells(job.numerics.cells, options.nested_min_cells);
  if (!cells) return std::nullopt;
  JobSpec coarse = job;
  coarse.numerics.cells = *cells;
  coarse.numerics.max_iterations = std::min(job.numerics.max_iterations, options.nested_max_iterations);
  coarse.numerics.stall_window = options.nested_stall_window;
  coarse.numerics.relax_stalled_correction = false;  // a stalled coarse level is a start (above), not a result
  SolveOptions quiet = options;
  quiet.on_iteration = {};
  quiet.vtk_dir.reset();
  quiet.checkpoint_file.reset();  // a checkpoint is of the job's own grid only
  quiet.resume_file.reset();
  spdlog::info("nested start: solving on {}x{}x{} cells first", (*cells)[0], (*cells)[1], (*cells)[2]);
  CoarseSolution sol;
  const JobResult r = solve_grid(coarse, particles, quiet, &sol);
  sol.usable = usable_start(r, coarse.numerics.tolerances.steady);
  sol.levels.push_back({{"cells", *cells},
                        {"status", solve_status_name(r.status)},
                        {"iterations", r.iterations},
                        {"used", sol.usable},
                        {"wall_s", r.wall_s}});
  if (!sol.usable)
    spdlog::info("nested start: the coarse solve ended {} after {} iterations; starting from the analytic warm start",
                 solve_status_name(r.status), r.iterations);
  else if (r.status != SolveStatus::kConverged)
    spdlog::info("nested start: the coarse solve stopped ({}) within {}× the steady tolerance; starting from it",
                 r.reason, kUsableStartFactor);
  return sol;
}

// The checkpoint to resume from, if options.resume_file names a usable one.
std::optional<Checkpoint> usable_checkpoint(const SolveOptions& options, const std::string& hash, const Grid& g) {
  if (!options.resume_file) return std::nullopt;
  if (!std::filesystem::exists(*options.resume_file)) {
    spdlog::info("no checkpoint at {}: starting from zero", options.resume_file->string());
    return std::nullopt;
  }
  auto cp = read_checkpoint(*options.resume_file, hash, g);
  if (auto* why = std::get_if<std::string>(&cp)) {
    spdlog::warn("ignoring the checkpoint {}: {}; starting from zero", options.resume_file->string(), *why);
    return std::nullopt;
  }
  return std::move(std::get<Checkpoint>(cp));
}

}  // namespace

SimpleSettings simple_settings_for(const NumericsSpec& numerics, const SimpleSettings& base) {
  SimpleSettings s = base;
  s.steady_tolerance = numerics.tolerances.steady;
  // tolerances.linear: the loosest relative residual an inner solve may stop
  // at (docs/SOLVER.md "Inner solves").
  s.momentum_tolerance = numerics.tolerances.linear;
  s.pressure_tolerance = numerics.tolerances.linear;
  s.linear_floor = std::min(s.linear_floor, numerics.tolerances.linear);
  s.max_iterations = numerics.max_iterations;
  s.stall_window = numerics.stall_window;
  s.relax_stalled_correction = numerics.relax_stalled_correction;
  return s;
}

Grid job_grid(const CaseSpec& case_spec, const std::array<int, 3>& cells) {
  Grid g;
  g.n = cells;
  g.length = case_spec.domain_cm();
  for (int a = 0; a < 3; ++a) g.periodic[a] = case_spec.periodic(a);
  return g;
}

JobResult solve_with_particles(const JobSpec& job, const ParticleSet& particles,
                               const SolveOptions& options) {
  return solve_grid(job, particles, options, nullptr);
}

namespace {

JobResult solve_grid(const JobSpec& job, const ParticleSet& particles, const SolveOptions& options,
                     CoarseSolution* keep) {
  const auto t0 = Clock::now();
  const double cpu0 = cpu_seconds();
  const CaseSpec& cs = job.case_spec;
  const NumericsSpec& num = job.numerics;
  JobResult result;

  // 1. Grid.
  FlowProblem problem;
  problem.grid = job_grid(cs, num.cells);
  problem.bc = cs.boundaries;
  problem.gas = {cs.gas.density_g_cm3, cs.gas.viscosity_g_cm_s, cs.gravity_cm_s2};
  problem.convection = num.convection;
  const Grid& g = problem.grid;
  const double d = cs.particle_diameter_cm;
  result.cells = num.cells;
  result.delta_star = g.delta_star(d);

  // 2–3. Particles and ε_s.
  const auto* uniform = std::get_if<UniformSpec>(&cs.particles);
  SolidsFraction sf = uniform ? uniform_solids_fraction(g, uniform->solids_fraction)
                              : deposit_solids_fraction(g, particles.particles, num.deposition, d,
                                                        num.tolerances.filter);
  result.particles = uniform ? 0 : static_cast<long>(particles.particles.size());
  result.max_solids_fraction = sf.max;
  if (sf.filtered) {
    result.extra["filter"] = {{"steps", sf.filter.steps},
                              {"iterations", sf.filter.total_iterations},
                              {"final_residual", sf.filter.worst_final_residual},
                              {"converged", sf.filter.converged}};
  }
  const double t_deposit = seconds_since(t0);
  auto finish = [&](JobResult& r) {
    r.wall_s = seconds_since(t0);
    r.cpu_s = cpu_seconds() - cpu0;
    r.peak_rss_mb = peak_rss_mb();
    r.extra["timing"]["deposition_s"] = t_deposit;
  };
  if (auto why = overfull_cell_reason(g, sf, d, num.deposition.kind == DepositionKind::kCentroid && !uniform)) {
    result.status = SolveStatus::kInvalid;  // no gas in a cell: the job has no solution to iterate towards
    result.reason = *why;
    finish(result);
    return result;
  }

  // 4. Nested start (a solution on a coarser grid), drag coupling, warm
  // start and outer iterations.
  const std::string hash = job_hash(job.source);
  std::optional<Checkpoint> resume = usable_checkpoint(options, hash, g);
  std::optional<CoarseSolution> coarse;
  if (!resume && options.nested_start && !options.cold_start) coarse = nested_start(job, particles, options);
  const DragSettings drag_settings{num.drag, d, cs.gas.density_g_cm3, cs.gas.viscosity_g_cm_s};
  std::optional<ParticleDragField> particle_drag;
  if (!uniform) {
    TransferSettings transfer{kernel_params(num.deposition, d), num.deposition.sampling, std::nullopt};
    if (is_filtered(num.deposition)) transfer.filter = filter_settings(num.deposition, d, num.tolerances.filter);
    particle_drag.emplace(g, particles.particles, drag_settings, transfer);
  }
  const DragUpdate drag = [&](const FlowState& st, DragField& out) {
    const auto u_cell = cell_centre_velocity(g, st.u);
    if (uniform) uniform_drag_field(g, drag_settings, uniform->solids_fraction, st.eps_g, u_cell, out);
    else particle_drag->compute(st.eps_g, u_cell, out);
  };
  FlowState state;
  warm_start(problem, sf.eps_s, drag, state, options.cold_start);
  std::unique_ptr<FasCoarseLevel> fas_coarse;  // the two-grid FAS prototype's coarse level
  if (coarse) {
    result.extra["nested_start"] = coarse->levels;
    if (coarse->usable) {
      state.p = prolong_cells(coarse->grid, coarse->p, g);
      state.u = prolong_faces(coarse->grid, coarse->u, g);
      if (options.simple.fas_smoothing_sweeps > 0)
        fas_coarse = make_fas_coarse_level(job, particles, coarse->grid, std::move(coarse->p), std::move(coarse->u));
    }
    coarse.reset();
  }
  LoopControl control;
  if (resume) {
    state.p = std::move(resume->state.p);
    state.u = std::move(resume->state.u);
    state.drag = std::move(resume->state.drag);
    control.resume = &resume->counters;
    result.extra["resumed_from_iteration"] = resume->counters.iteration;
    spdlog::info("resuming from the checkpoint after iteration {}", resume->counters.iteration);
  }
  control.stop_requested = options.stop_requested;
  bool checkpoint_written = false;
  if (options.checkpoint_file)
    control.on_stop = [&](const FlowState& st, const LoopCounters& counters) {
      write_checkpoint(*options.checkpoint_file, hash, g, st, counters);
      checkpoint_written = true;
      spdlog::info("checkpoint after iteration {} written to {}", counters.iteration, options.checkpoint_file->string());
    };

  const double u0 = inflow_velocity(problem.bc);
  const double y1 = cs.probes.y1_dp * d, y2 = cs.probes.y2_dp * d;
  QuantityOfInterest qoi;
  if (u0 != 0.0)
    qoi = [&](const FlowState& st) { return dp_star(g, st.p, y1, y2, problem.gas.rho, u0); };

  const SimpleSettings settings = simple_settings_for(num, options.simple);
  const auto t_iter = Clock::now();
  SimpleOutcome out;
  if (fas_coarse) {
    const FasOutcome fas =
        run_two_grid_fas(FasLevel{&problem, &state, drag}, fas_coarse->level, settings, qoi, options.on_iteration);
    out = fas.outcome;
    result.extra["fas"] = {{"cycles", fas.cycles}, {"coarse_sweeps", fas.coarse_sweeps}};
    fas_coarse.reset();
  } else if (settings.newton_krylov_restart > 0) {
    out = run_newton_krylov(problem, settings, state, drag, qoi, options.on_iteration, control);
  } else {
    out = run_simple(problem, settings, state, drag, qoi, options.on_iteration, control);
  }
  const double t_iterations = seconds_since(t_iter);
  if (out.stopped) throw SolveStopped(out.iterations, checkpoint_written);

  // 5. Result.
  result.status = out.status;
  result.reason = out.reason;
  result.stalled = out.stalled;
  if (out.correction_relaxed_from > 0) result.extra["correction_relaxed_from_iteration"] = out.correction_relaxed_from;
  result.iterations = out.iterations;
  result.residual_continuity = out.continuity;
  result.residual_momentum = out.momentum;
  result.dp_star_change = out.qoi_change;
  if (out.qoi && std::isfinite(*out.qoi)) result.dp_star = out.qoi;
  FaceVector flux;
  compute_mass_fluxes(problem, state, flux);
  const BoundaryFlux bf = boundary_mass_flux(problem, flux);
  result.mass_imbalance = bf.in > 0 ? std::abs(bf.in - bf.out) / bf.in : 0.0;
  if (!std::isfinite(result.mass_imbalance)) result.mass_imbalance = 0.0;
  result.extra["timing"]["iterations_s"] = t_iterations;
  result.extra["timing"]["drag_s"] = out.seconds.drag;
  result.extra["timing"]["momentum_s"] = out.seconds.momentum;
  result.extra["timing"]["pressure_s"] = out.seconds.pressure;
  if (out.qoi_iterative_error) result.extra["dp_star_iterative_error"] = *out.qoi_iterative_error;
  result.extra["settings"] = {{"algorithm", "SIMPLEC"},
                              {"relax_u", settings.relax_u},
                              {"relax_p", settings.relax_p},
                              {"momentum_tolerance", settings.momentum_tolerance},
                              {"pressure_tolerance", settings.pressure_tolerance},
                              {"drag_interval", settings.drag_interval}};
  if (result.extra.contains("fas")) {
    result.extra["settings"]["algorithm"] = "two-grid FAS with SIMPLEC smoothing";
    result.extra["settings"]["fas_smoothing_sweeps"] = settings.fas_smoothing_sweeps;
    result.extra["settings"]["fas_coarse_sweeps"] = settings.fas_coarse_sweeps;
  } else if (settings.newton_krylov_restart > 0) {
    result.extra["settings"]["algorithm"] = "Newton-Krylov on SIMPLEC";
    result.extra["settings"]["gmres_restart"] = settings.newton_krylov_restart;
    result.extra["newton_krylov"] = {{"steps", out.newton_steps}, {"fallbacks", out.newton_fallbacks}};
  }
  if (out.linear_failures) result.extra["linear_solver_warnings"] = true;
  if (particle_drag) {
    result.extra["drag_updates"] = particle_drag->updates();
    result.extra["interphase_force_imbalance"] = particle_drag->last_imbalance();  // coupling/drag_field.h
  }

  if (options.vtk_dir) {
    const auto file = *options.vtk_dir / (cs.name.empty() ? std::string("fields.vtk") : cs.name + ".vtk");
    write_vtk(file, g, sf.eps_s, state);
    result.extra["vtk"] = file.filename().string();
  }
  finish(result);
  if (keep) {
    keep->grid = g;
    keep->p = std::move(state.p);
    keep->u = std::move(state.u);
    if (result.extra.contains("nested_start")) keep->levels = result.extra["nested_start"];
  }
  return result;
}

}  // namespace
}  // namespace gridfree

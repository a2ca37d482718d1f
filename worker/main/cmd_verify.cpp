// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree-worker verify [--json] [--quick] [--scheme NAME]... [--grids N...] [--threads N]
// Code verification with manufactured solutions: observed vs expected order
// of accuracy for every convection scheme and for the filter; the grids of
// all studies are solved concurrently on the threads. Exit 0 only if
// every observed order is within 0.2 of the expected one (or above).
#include <omp.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "commands.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "thread_count.h"
#include "verify/verify.h"

namespace gridfree::worker_cli {
namespace {

struct VerifyArgs {
  bool json = false;
  bool quick = false;
  std::vector<std::string> schemes;
  std::vector<int> grids;  // empty: the default set
  int threads = 0;  // 0 = OMP_NUM_THREADS, else all cores
};

void print_table(const std::vector<OrderStudy>& studies) {
  std::printf("%-26s %-22s %-18s %9s %9s  %s\n", "equation", "scheme", "norm", "expected", "observed", "");
  for (const auto& s : studies) {
    std::printf("%-26s %-22s %-18s %9.2f %9.2f  %s\n", s.equation.c_str(), s.scheme.c_str(), s.norm.c_str(),
                s.expected_order, s.observed_order, s.passed() ? "ok" : "FAILED");
    if (!s.failure.empty()) std::printf("    %s\n", s.failure.c_str());
  }
}

int run(const VerifyArgs& args) {
  use_thread_count(args.threads);
  omp_set_max_active_levels(1);  // one problem per thread: the solvers' own loops stay serial
  VerifyOptions options;
  options.quick = args.quick;
  for (std::size_t i = 0; i < args.grids.size(); ++i)
    if (args.grids[i] < 4 || (i > 0 && args.grids[i] <= args.grids[i - 1]))
      throw InputError("--grids", "cells per direction must be at least 4 and increasing, got " +
                                      std::to_string(args.grids[i]) + " at position " + std::to_string(i + 1));
  options.grids = args.grids;
  for (std::size_t i = 0; i < args.schemes.size(); ++i) {
    const auto limiter = limiter_from_name(args.schemes[i]);
    if (!limiter)
      throw InputError("--scheme", "'" + args.schemes[i] + "' is not one of " + limiter_names());
    options.schemes.push_back(*limiter);
  }
  options.on_study = [](const OrderStudy& s) {
    spdlog::info("{} {}: observed order {:.2f} (expected {:.1f})", s.equation, s.scheme, s.observed_order,
                 s.expected_order);
  };
  const std::vector<OrderStudy> studies = run_code_verification(options);
  bool all_passed = true;
  for (const auto& s : studies) all_passed = all_passed && s.passed();
  if (args.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& s : studies) out.push_back(to_json(s));
    std::cout << out.dump(2) << '\n';
  } else {
    print_table(studies);
  }
  return to_int(all_passed ? ExitCode::kOk : ExitCode::kNotConverged);
}

}  // namespace

void add_verify_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<VerifyArgs>();
  auto* sub = app.add_subcommand("verify", "Code verification: manufactured solutions, observed vs expected order");
  sub->add_flag("--json", args->json, "Print the results as JSON");
  sub->add_flag("--quick", args->quick, "Coarser, fewer grids (seconds instead of minutes)");
  sub->add_option("--scheme", args->schemes, "Only these convection schemes (repeatable)");
  sub->add_option("--grids", args->grids,
                  "cells per direction of every study's grids, coarse to fine (default 16 32 64 128; "
                  "--quick 16 32 64)");
  sub->add_option("--threads", args->threads, "problems solved at once (default: OMP_NUM_THREADS, else all cores)");
  sub->callback([args, &exit_code] {
    spdlog::set_level(args->json ? spdlog::level::warn : spdlog::level::info);
    exit_code = run(*args);
  });
}

}  // namespace gridfree::worker_cli

// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree extrapolate SERIES.json|SERIES.csv [--method averaged|capped|fm|eh14] [--p-range lo hi] [--order P] [--self-check]
//
// Applies the extrapolation of PHYSICS.md §8 to any series a user brings
// ({"h": [...], "f": [...]} or a CSV with columns h,f) and prints the JSON of
// docs/INTERFACE.md §4 (2-space indent) on stdout. --self-check adds
// "self_check": the coverage of U on the series' coarser windows
// (extrap/self_check.h), its one-line summary also on stderr; a series whose
// check falls below the promise is not `converged`. --order declares the
// formal order (extrap/bias_checks.h). Exit 0 on success, 2 on invalid
// input (the message names the file position or JSON path and why).
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "commands.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "extrap/coverage_record.h"
#include "extrap/extrapolation.h"
#include "extrap/self_check.h"
#include "extrap/series_io.h"
#include "extrap/value_format.h"

namespace gridfree::cli {
namespace {

struct ExtrapolateArgs {
  std::string series_file;
  std::string method = "averaged";
  std::vector<double> p_range;
  double order = 0;  // 0: no formal order declared
  bool self_check = false;
  bool no_leave_one_out = false;
  bool no_range_floor = false;
};

int run_extrapolate(const ExtrapolateArgs& args) {
  try {
    ExtrapolationOptions opts;
    opts.method = parse_method(args.method, "--method");
    if (!args.p_range.empty()) {
      opts.p_low = args.p_range[0];
      opts.p_high = args.p_range[1];
    }
    if (args.order > 0) opts.expected_order = args.order;
    opts.leave_one_out = !args.no_leave_one_out;
    opts.unreliable_range_floor = !args.no_range_floor;
    validate_options(opts);
    const Series series = read_series_file(args.series_file);
    ExtrapolationResult result = extrapolate(series, opts);
    std::optional<CoverageCheck> check;
    if (args.self_check) {
      check = coverage_self_check(series.h, series.f, [&opts](const auto& h, const auto& f) {
        return window_fit(extrapolate(Series{h, f}, opts));
      });
      demote_if_flagged(*check, series.h, result.verdict);
      std::cerr << check->summary() << '\n';
    }
    // The answer for people on stderr, in the digits the report prints
    // (extrap/value_format.h); stdout stays the JSON.
    const GridUncertainty* finest = result.grids.empty() ? nullptr : &result.grids.front();
    const std::optional<double> f1 = finest ? std::optional<double>(finest->f) : std::nullopt;
    std::cerr << verdict_line(result.verdict.value, result.f0, result.u0, f1, finest ? finest->u : std::nullopt,
                              finest ? finest->rde : std::nullopt)
              << '\n';
    auto out = to_ordered_json(result);
    out["coverage"] = measured_coverage_json(opts.method, opts.expected_order.has_value());
    if (check) out["self_check"] = to_ordered_json(*check);
    std::cout << out.dump(2) << '\n';
    return to_int(ExitCode::kOk);
  } catch (const InputError& e) {
    print_input_error(std::cerr, e);
    return to_int(ExitCode::kInvalidInput);
  }
}

}  // namespace

void add_extrapolate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ExtrapolateArgs>();
  auto* sub = app.add_subcommand(
      "extrapolate", "Extrapolate a grid series to h -> 0 with uncertainties (docs/PHYSICS.md §8); prints JSON");
  sub->add_option("series", args->series_file, "SERIES.json ({\"h\": [...], \"f\": [...]}) or SERIES.csv (columns h,f)")
      ->required();
  sub->add_option("--method", args->method,
                  "averaged (default: capped, with U holding f0 of every admissible error expansion), "
                  "capped (Fullmer & Musser 2018 with observed orders above the range capped), "
                  "fm (Fullmer & Musser 2018 as published) or eh14 (Eca & Hoekstra 2014)")
      ->check(CLI::IsMember({"averaged", "capped", "fm", "eh14"}));
  sub->add_option("--p-range", args->p_range, "accepted observed orders lo hi (default 0.5 2.1)")
      ->expected(2);
  sub->add_option("--order", args->order,
                  "the formal order of the discretization: a series whose observed order contradicts it, "
                  "is not converged, and U grows with |p/P - 1| (Xing & Stern 2010)")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--no-leave-one-out", args->no_leave_one_out,
                "skip the leave-one-out test (f0 without the coarsest and without the finest grid): the "
                "procedure as it was before that test, for comparison");
  sub->add_flag("--no-range-floor", args->no_range_floor,
                "averaged: leave an unreliable result's U below 3 times the data range per refinement: the "
                "method as it was before that floor, for comparison");
  sub->add_flag("--self-check", args->self_check,
                "re-extrapolate every window of 4-8 consecutive coarser grids and report whether its U "
                "covered the whole series' f0 (needs >= 6 grids)");
  sub->callback([args, &exit_code] { exit_code = run_extrapolate(*args); });
}

}  // namespace gridfree::cli

// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree extrapolate SERIES.json|SERIES.csv [--method capped|fm|eh14] [--p-range lo hi] [--self-check]
//
// Applies the extrapolation of PHYSICS.md §8 to any series a user brings
// ({"h": [...], "f": [...]} or a CSV with columns h,f) and prints the JSON of
// docs/INTERFACE.md §4 (2-space indent) on stdout. --self-check adds
// "self_check": the coverage of U on the series' coarser windows
// (extrap/self_check.h), its one-line summary also on stderr. Exit 0 on success, 2 on invalid
// input (the message names the file position or JSON path and why).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_errors.h"
#include "commands.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "extrap/extrapolation.h"
#include "extrap/self_check.h"
#include "extrap/series_io.h"
#include "extrap/value_format.h"

namespace gridfree::cli {
namespace {

struct ExtrapolateArgs {
  std::string series_file;
  std::string method = "capped";
  std::vector<double> p_range;
  bool self_check = false;
};

int run_extrapolate(const ExtrapolateArgs& args) {
  try {
    ExtrapolationOptions opts;
    opts.method = parse_method(args.method, "--method");
    if (!args.p_range.empty()) {
      opts.p_low = args.p_range[0];
      opts.p_high = args.p_range[1];
    }
    validate_options(opts);
    const Series series = read_series_file(args.series_file);
    const ExtrapolationResult result = extrapolate(series, opts);
    auto out = to_ordered_json(result);
    if (args.self_check) {
      const auto check = coverage_self_check(series.h, series.f, [&opts](const auto& h, const auto& f) {
        return window_fit(extrapolate(Series{h, f}, opts));
      });
      out["self_check"] = to_ordered_json(check);
      std::cerr << check.summary() << '\n';
    }
    // The answer for people on stderr, in the digits the report prints
    // (extrap/value_format.h); stdout stays the JSON.
    const GridUncertainty* finest = result.grids.empty() ? nullptr : &result.grids.front();
    const std::optional<double> f1 = finest ? std::optional<double>(finest->f) : std::nullopt;
    std::cerr << verdict_line(result.verdict.value, result.f0, result.u0, f1, finest ? finest->u : std::nullopt,
                              finest ? finest->rde : std::nullopt)
              << '\n';
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
                  "capped (default: Fullmer & Musser 2018 with observed orders above the range capped), "
                  "fm (Fullmer & Musser 2018 as published) or eh14 (Eca & Hoekstra 2014)")
      ->check(CLI::IsMember({"capped", "fm", "eh14"}));
  sub->add_option("--p-range", args->p_range, "accepted observed orders lo hi (default 0.5 2.1)")
      ->expected(2);
  sub->add_flag("--self-check", args->self_check,
                "re-extrapolate every window of 4-8 consecutive coarser grids and report whether its U "
                "covered the whole series' f0 (needs >= 6 grids)");
  sub->callback([args, &exit_code] { exit_code = run_extrapolate(*args); });
}

}  // namespace gridfree::cli

// gridfree extrapolate SERIES.json|SERIES.csv [--method fm|eh14] [--p-range lo hi]
//
// Applies the extrapolation of PHYSICS.md §8 to any series a user brings
// ({"h": [...], "f": [...]} or a CSV with columns h,f) and prints the JSON of
// docs/INTERFACE.md §4 (2-space indent) on stdout. Exit 0 on success, 2 on invalid
// input (the message names the file position or JSON path and why).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "extrap/extrapolation.h"
#include "extrap/series_io.h"

namespace gridfree::cli {
namespace {

struct ExtrapolateArgs {
  std::string series_file;
  std::string method = "fm";
  std::vector<double> p_range;
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
    std::cout << to_ordered_json(result).dump(2) << '\n';
    return to_int(ExitCode::kOk);
  } catch (const InputError& e) {
    std::cerr << "error: invalid input\n" << e.what() << '\n';
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
  sub->add_option("--method", args->method, "fm (Fullmer & Musser 2018, default) or eh14 (Eca & Hoekstra 2014)")
      ->check(CLI::IsMember({"fm", "eh14"}));
  sub->add_option("--p-range", args->p_range, "accepted observed orders lo hi (default 0.5 2.1)")
      ->expected(2);
  sub->callback([args, &exit_code] { exit_code = run_extrapolate(*args); });
}

}  // namespace gridfree::cli

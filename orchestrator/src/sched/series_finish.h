// SPDX-License-Identifier: GPL-3.0-or-later
// What happens when a series' last job finishes: extrapolate its converged
// points (h = Δ*, f = dp_star; PHYSICS.md §8, through the report's
// Extrapolator seam), store its fits (one row each, `chosen` on the
// selected one) and one uncertainty row per converged job, mark it done.
// Also: the study report, rebuilt from the store.
#pragma once

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/extrapolator.h"
#include "report/extrapolation_memo.h"
#include "report/report_data.h"
#include "report/report_stop.h"
#include "store/store.h"

namespace gridfree {

// Extrapolation settings of a stored study (its definition's "extrapolation").
ExtrapolatorSettings study_extrapolation_settings(Store& store, long long study_id);

// The `extrapolations.method` row f0 comes from: "capped" for capped_power,
// the fit's name for eh14_<fit>_<weighting>, else the method itself.
std::string chosen_fit_name(const std::string& method);

// Splits the contract extrapolation JSON (docs/INTERFACE.md §4) into rows, one
// per reported fit (power, mixed, and capped/first/second when present;
// "constant" for constant data), `chosen` on chosen_fit_name(method); grids
// are matched to jobs by h.
void extrapolation_rows(const nlohmann::json& ex, const std::vector<SeriesPoint>& points,
                        std::vector<ExtrapolationRow>& fits, std::vector<UncertaintyRow>& uncertainties);

// Extrapolates and stores one series. Returns the extrapolation JSON.
nlohmann::json finish_series(Store& store, const SeriesInfo& series, const Extrapolator& extrapolate);

// Finishes every ready series of the study and refreshes its status.
// Returns the number of series finished.
int finish_ready_series(Store& store, long long study_id);

// After one job's final result: finishes the series of that job that it made
// ready (an index lookup, whatever the study's size) and refreshes the
// study's status. An adaptive study (`adaptive`: its definition has
// adaptive grids) is swept whole, as its decisions may add jobs.
int finish_series_of_job(Store& store, long long study_id, long long job_id, bool adaptive);

// Everything the report shows, from the store.
StudyReportData build_report_data(Store& store, long long study_id);

// build_report_data + write_study_report into out_dir; returns the HTML path.
// `stop`: see report/report_stop.h (throws ReportInterrupted). `memo`: the
// study's extrapolations of earlier writes (report/extrapolation_memo.h),
// kept by a caller that writes the report again and again.
std::filesystem::path write_report(Store& store, long long study_id, const std::filesystem::path& out_dir,
                                   const StopRequested& stop = {}, ExtrapolationMemo* memo = nullptr);

}  // namespace gridfree

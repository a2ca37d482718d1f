// SPDX-License-Identifier: GPL-3.0-or-later
// Ensemble statistics of the report (docs/EXTRAPOLATION.md "Ensembles"):
// for every ensemble and configuration (convection × fwhm_dp × drag ×
// deposition; an external study's: its factor levels × quantity), the instances' f0 and, per Δ*, their U and RDE = U/|f0|.
//
//   mean  x̄ = Σ x_i / n,   sample sd  s = sqrt(Σ (x_i − x̄)² / (n − 1))  (n ≥ 2),
//   standard error of the mean  s/√n,   relative spread  s/|x̄|.
//
// Averaging rule: f0 is averaged over every instance that has an f0,
// whatever its verdict; `converged` counts the instances whose verdict is
// converged and the report flags a configuration where it is less than the
// number of instances. U and RDE at a Δ* are averaged over the instances
// with a value at that Δ* (grids are matched by Δ*: the instances of an
// ensemble share the domain, so grid i has the same Δ* in each).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/series_summary.h"
#include "study/case_vocabulary.h"

namespace gridfree {

struct SampleStats {
  int n = 0;
  double mean = 0, min = 0, max = 0;
  std::optional<double> sd, sem;      // n ≥ 2
  // s/|x̄|; empty without sd or when x̄ = 0.
  std::optional<double> relative_sd() const;
};

// Statistics of the finite values; empty when there is none.
std::optional<SampleStats> sample_stats(const std::vector<double>& values);

struct EnsembleGrid {
  double delta_star = 0;
  std::vector<double> u, rde;         // one per instance with a value here
  std::optional<SampleStats> u_stats, rde_stats;
};

struct EnsembleConfig {
  std::string ensemble;
  std::string convection, drag, deposition;
  double fwhm_dp = 0;
  // An external configuration (docs/EXTERNAL.md "Factors, designs and
  // ensembles"): its quantity and the study's own factor levels.
  std::string quantity{};
  std::map<std::string, std::string> levels{};
  // Its factors (series_factors without the case) and its case's words
  // (report/series_vocabulary.h), from its first instance.
  std::vector<std::pair<std::string, std::string>> factors{};
  CaseVocabulary vocabulary{};
  std::vector<std::size_t> members;   // indices into the summaries (instances with this configuration)
  std::vector<std::string> instances; // their case names
  int converged = 0;                  // members with verdict converged
  std::vector<std::string> without_f0;  // instances with no f0 (left out of the mean)
  std::optional<SampleStats> f0;
  std::vector<EnsembleGrid> grids;    // Δ* ascending

  std::string label() const;          // "sscp: superbee fwhm6 bvk" (+ deposition); external "seeds: scheme=QUICK T_mean"
  bool external() const { return !quantity.empty(); }
  bool flagged() const { return converged < static_cast<int>(members.size()); }
};

// One EnsembleConfig per (ensemble, configuration) present among the
// summaries, ensembles by name, configurations in series order.
std::vector<EnsembleConfig> ensemble_configs(const std::vector<SeriesSummary>& series,
                                             const std::map<std::string, std::vector<std::string>>& ensembles);

}  // namespace gridfree

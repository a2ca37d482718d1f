// SPDX-License-Identifier: GPL-3.0-or-later
// Synthetic study data and a stand-in extrapolator for the report tests.
//
// Three series:
//   A  PC1 superbee fwhm6 bvk   f = 1000 + 8h on 4 grids (all converged)
//   B  PC1 superbee fwhm6 hkl   f = 1500 + 10h² on 4 grids + 1 diverged grid
//   C  PC2 superbee fwhm6 bvk   f = 990 + 4h on 3 grids + 1 queued (incomplete)
// A–B differ only in drag, A–C only in case, B–C in two factors.
//
// The stand-in extrapolator plays the library's part with exact answers:
// for ng ≥ 4 it returns the known f0, p, c of the manufactured data, the
// data range R_f = (max f − min f)/(ng − 1), σ_RE = kSigma, Fs = 1.25 and
// U_i = Fs|f0 − f_i| + σ_RE, RDE_i = U_i/|f0| (PHYSICS.md §8); for ng < 4 it
// returns "insufficient_grids" with null numbers; verdict A converged, B
// pre-asymptotic (none for ng < 4). GCI triplets carry
// φ_ext = f0 + 100·(triplet index) so tests can find them.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/report_data.h"
#include "report/series_summary.h"

namespace gridfree::test {

inline constexpr double kSigma = 0.5;
inline constexpr double kFs = 1.25;

struct Manufactured {
  double f0, c, p;
  double f(double h) const { return f0 + c * std::pow(h, p); }
};

inline const Manufactured kA{1000, 8, 1}, kB{1500, 10, 2}, kC{990, 4, 1};

inline GridPoint grid(double h, const Manufactured& m, const std::string& status = "converged") {
  GridPoint g;
  g.job_hash = "hash-" + std::to_string(h);
  g.delta_star = h;
  g.nx = static_cast<int>(std::lround(30 / h));
  g.ny = static_cast<int>(std::lround(200 / h));
  g.nz = static_cast<int>(std::lround(10 / h));
  g.status = status;
  if (status == "converged") g.dp_star = m.f(h);
  g.iterations = 100 + static_cast<int>(100 / h);
  g.wall_s = 10 / (h * h * h);
  g.cpu_s = 2 * g.wall_s;
  g.peak_rss_mb = 50 + 20 / h;
  return g;
}

inline StudyReportData synthetic_study() {
  StudyReportData d;
  d.study_name = "synthetic <study>";
  d.status = "running";
  d.submitted_at = "2024-01-01 10:00:00";
  d.version = "gridfree 0.1.0 (test)";
  d.baseline_description = "one_at_a_time: PC1 superbee fwhm6 bvk";

  SeriesData a{1, "PC1", "superbee", "bvk", "diffusion", 6, "done", {}, {}};
  for (double h : {2.0, 1.0, 0.5, 1.5}) a.grids.push_back(grid(h, kA));  // unsorted on purpose
  SeriesData b{2, "PC1", "superbee", "hkl", "diffusion", 6, "done", {}, {}};
  for (double h : {0.5, 1.0, 1.5, 2.0}) b.grids.push_back(grid(h, kB));
  GridPoint bad = grid(0.25, kB, "diverged");
  bad.reason = "residual grew by 1e6, diverged at iteration 12";
  b.grids.push_back(bad);
  SeriesData c{3, "PC2", "superbee", "bvk", "diffusion", 6, "running", {}, {}};
  for (double h : {1.0, 1.5, 2.0}) c.grids.push_back(grid(h, kC));
  c.grids.push_back(grid(0.5, kC, "queued"));
  d.series = {a, b, c};
  return d;
}

// The manufactured series whose data these are (matched by f at the coarsest h).
inline const Manufactured& manufactured_for(const std::vector<double>& h, const std::vector<double>& f) {
  for (const Manufactured* m : {&kA, &kB, &kC}) {
    if (std::abs(m->f(h.back()) - f.back()) < 1e-9) return *m;
  }
  return kA;
}

inline nlohmann::json fake_extrapolation(const std::vector<double>& h, const std::vector<double>& f) {
  using nlohmann::json;
  const std::size_t n = h.size();
  const Manufactured& m = manufactured_for(h, f);
  const double range = n > 1 ? (*std::max_element(f.begin(), f.end()) - *std::min_element(f.begin(), f.end())) / double(n - 1) : 0.0;
  json j;
  const bool enough = n >= 4;
  j["status"] = enough ? "ok" : "insufficient_grids";
  j["method"] = enough ? json(m.p == 1 ? "power" : "mixed") : json(nullptr);
  j["f0"] = enough ? json(m.f0) : json(nullptr);
  j["p"] = enough ? json(m.p) : json(nullptr);
  j["sigma_re"] = enough ? json(kSigma) : json(nullptr);
  j["data_range"] = range;
  j["fs"] = enough ? json(kFs) : json(nullptr);
  j["fits"]["power"] = {{"f0", m.f0}, {"p", m.p}, {"c", m.c}, {"sigma", kSigma}, {"p_found", true}};
  j["fits"]["mixed"] = {{"f0", m.f0}, {"c1", m.p == 1 ? m.c : 0.0}, {"c2", m.p == 2 ? m.c : 0.0}, {"sigma", kSigma}};
  j["grids"] = json::array();
  for (std::size_t i = 0; i < n; ++i) {
    const double u = kFs * std::abs(m.f0 - f[i]) + kSigma;
    j["grids"].push_back({{"h", h[i]}, {"f", f[i]}, {"fhat", m.f(h[i])},
                          {"u", enough ? json(u) : json(nullptr)},
                          {"rde", enough ? json(u / m.f0) : json(nullptr)}});
  }
  j["gci"] = json::array();
  for (std::size_t i = 0; i + 2 < n; ++i) {
    j["gci"].push_back({{"h", {h[i], h[i + 1], h[i + 2]}}, {"p", m.p}, {"f_ext", m.f0 + 100.0 * double(i)},
                        {"gci_fine", 0.001}, {"convergence", "monotone"}, {"status", "ok"}});
  }
  j["notes"] = json::array();
  // A is converged, B pre-asymptotic (so the charts and the cost table see
  // both kinds); C (ng < 4) gets no verdict from the stand-in.
  if (enough)
    j["verdict"] = {{"value", &m == &kA ? "converged" : "pre-asymptotic"},
                    {"reasons", json::array({"stand-in verdict"})},
                    {"next_h", nullptr}};
  return j;
}

// The synthetic study's series summarized with the stand-in extrapolator.
inline std::vector<SeriesSummary> synthetic_summaries() {
  return summarize_series(synthetic_study(), fake_extrapolation);
}

}  // namespace gridfree::test

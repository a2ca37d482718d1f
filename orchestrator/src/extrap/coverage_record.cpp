// SPDX-License-Identifier: GPL-3.0-or-later
// Measured coverage of each method (see coverage_record.h). The numbers are
// the "all sources" rows of bench/coverage/corpus.py in docs/EXTRAPOLATION.md
// "Coverage on other codes' series"; change them only with a new measurement.
#include "extrap/coverage_record.h"

#include <cstdio>
#include <utility>

namespace gridfree {

namespace {

constexpr const char* kCorpus =
    "bench/coverage/corpus: 111 series, 1165 windows of 4 to n-1 grids: NASA TMR 2-D NACA 0012 "
    "(CFL3D, FUN3D, TAU; 85 series), OpenFOAM laplacianFoam conduction and scalarTransportFoam "
    "advection-diffusion (exact), this worker's manufactured solutions (exact), 13 bursting-bubble "
    "series of this worker (2 with a held-out reference)";
constexpr const char* kMeasured = "2026-12-07, bench/coverage/corpus.py GRIDFREE --estimators METHOD[+order]";

MeasuredCoverage record(const char* method, bool with_order, std::vector<ClassCoverage> classes,
                        const char* shortfall) {
  return {method, kCorpus, kMeasured, with_order, std::move(classes), shortfall};
}

}  // namespace

MeasuredCoverage measured_coverage(ExtrapolationMethod method, bool with_order) {
  switch (method) {
    case ExtrapolationMethod::kAveraged:
      return with_order ? record("averaged", true,
                                 {{"converged", 269, 1.000, 1.000}, {"pre-asymptotic", 404, 0.988, 0.995},
                                  {"unreliable", 492, 0.984, 0.984}},
                                 "")
                        : record("averaged", false,
                                 {{"converged", 287, 0.993, 0.993}, {"pre-asymptotic", 392, 0.982, 0.990},
                                  {"unreliable", 486, 0.984, 0.984}},
                                 "NACA 0012 alone, converged windows: 31 of 33 (94 %, worst miss 3.2 U1: CFL3D "
                                 "moment, p = 1.35, which a declared order catches)");
    case ExtrapolationMethod::kCapped:
      return with_order ? record("capped", true,
                                 {{"converged", 285, 0.986, 0.993}, {"pre-asymptotic", 400, 0.968, 0.968},
                                  {"unreliable", 480, 0.942, 0.948}},
                                 "unreliable windows 94.2 %; NACA 0012 alone: converged 18 of 22 (82 %), "
                                 "pre-asymptotic 93 %, unreliable 89 %")
                        : record("capped", false,
                                 {{"converged", 304, 0.954, 0.980}, {"pre-asymptotic", 391, 0.939, 0.944},
                                  {"unreliable", 470, 0.860, 0.874}},
                                 "pre-asymptotic 94 %, unreliable 86 %; NACA 0012 alone: converged 25 of 34 (74 %, "
                                 "worst miss 6.4 U1), unreliable 73 %");
    case ExtrapolationMethod::kFm:
      return with_order ? record("fm", true,
                                 {{"converged", 282, 0.986, 0.993}, {"pre-asymptotic", 275, 0.905, 0.938},
                                  {"unreliable", 608, 0.873, 0.849}},
                                 "pre-asymptotic 90.5 %, unreliable 87 %; NACA 0012 alone: converged 18 of 22 (82 %)")
                        : record("fm", false,
                                 {{"converged", 301, 0.953, 0.980}, {"pre-asymptotic", 262, 0.866, 0.927},
                                  {"unreliable", 602, 0.772, 0.772}},
                                 "pre-asymptotic 87 %, unreliable 77 %; NACA 0012 alone: converged 25 of 34 (74 %, "
                                 "worst miss 6.4 U1)");
    case ExtrapolationMethod::kEh14:
    default:
      return with_order ? record("eh14", true,
                                 {{"converged", 284, 0.993, 0.996}, {"pre-asymptotic", 406, 0.980, 0.968},
                                  {"unreliable", 475, 0.962, 0.935}},
                                 "unreliable windows f0 +- U0 93.5 %; NACA 0012 alone: converged 19 of 21 (90 %), "
                                 "unreliable 93 %")
                        : record("eh14", false,
                                 {{"converged", 301, 0.967, 0.980}, {"pre-asymptotic", 400, 0.973, 0.953},
                                  {"unreliable", 464, 0.914, 0.864}},
                                 "unreliable 91 %; NACA 0012 alone: converged 26 of 31 (84 %, worst miss 5.8 U1), "
                                 "unreliable 84 %");
  }
}

std::string measured_coverage_sentence(ExtrapolationMethod method, bool with_order, const std::string& verdict) {
  const MeasuredCoverage m = measured_coverage(method, with_order);
  for (const auto& c : m.classes) {
    if (c.verdict != verdict) continue;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "method %s (%s) was measured on the development corpus (bench/coverage/corpus) to cover the "
                  "reference in %.0f %% of %s windows with f1 +- U1 and %.0f %% with f0 +- U0",
                  m.method.c_str(), with_order ? "formal order declared" : "no formal order declared",
                  100 * c.u1, verdict.c_str(), 100 * c.u0);
    std::string s = buf;
    if (!m.shortfall.empty()) s += "; short of 95 %: " + m.shortfall;
    return s;
  }
  return {};
}

nlohmann::ordered_json measured_coverage_json(ExtrapolationMethod method, bool with_order) {
  using ojson = nlohmann::ordered_json;
  const MeasuredCoverage m = measured_coverage(method, with_order);
  ojson classes = ojson::object();
  for (const auto& c : m.classes) classes[c.verdict] = ojson{{"windows", c.windows}, {"u1", c.u1}, {"u0", c.u0}};
  return ojson{{"method", m.method},
               {"order_declared", m.with_order},
               {"corpus", m.corpus},
               {"measured", m.measured},
               {"classes", classes},
               {"shortfall", m.shortfall.empty() ? ojson(nullptr) : ojson(m.shortfall)}};
}

}  // namespace gridfree

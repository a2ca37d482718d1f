// SPDX-License-Identifier: GPL-3.0-or-later
// gci_NN_<series>.svg: the classic three-grid extrapolation (Celik et al.
// 2008, orchestrator/src/extrap/gci.h) of every consecutive triplet beside
// the regression's f_i ± U_i and f0. For each triplet, at its finest grid
// h1: the GCI band φ1 ± GCI_fine·|φ1| as an error bar whose marker gives the
// convergence type (monotone ●, oscillatory ▲, divergent ✕), and φ_ext as
// a diamond. The y range follows the regression data; values far outside
// it are arrows on the edge.
#pragma once

#include <cstddef>

#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

// A chart with no series when the series has no GCI triplet.
Chart gci_chart(const SeriesSummary& series, std::size_t index);

}  // namespace gridfree

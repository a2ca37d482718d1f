// SPDX-License-Identifier: GPL-3.0-or-later
// speed_accuracy.svg and speed_accuracy_work.svg: what a target accuracy
// costs. Per series, every converged grid as (a-priori RDE = U_i/|f0| of
// docs/PHYSICS.md §8, cost), the cost being its CPU time (this machine) or
// cells × outer iterations (machine-independent). A grid is *dominated* when
// another grid of the same series is at least as accurate (RDE ≤) and at
// most as expensive (cost ≤), and strictly better in one of the two: nobody
// should run it. Dominated grids are drawn faded; the others, the Pareto
// front, are connected in order of RDE. Only `converged` series get a front:
// the others are drawn hollow and dashed (legend "label (verdict)"), never as
// a front, and without any converged series the chart has no series (and is
// not written, report_charts.cpp). Axes log when the data span more than a
// decade (chart_axis.h scale_for_span).
#pragma once

#include <cstddef>
#include <vector>

#include "report/series_summary.h"
#include "report/svg_chart.h"

namespace gridfree {

struct CostPoint {
  double rde = 0;   // a-priori RDE (fraction)
  double cost = 0;  // CPU s or cells × iterations
};

// Indices of the non-dominated points (non-finite points are never on the
// front), sorted by RDE ascending (ties by cost). Equal points are all kept.
std::vector<std::size_t> pareto_front(const std::vector<CostPoint>& points);

// cell_iterations: cells × iterations (any machine); cells: the size alone,
// for a code whose results report no iterations (study/case_vocabulary.h).
enum class CostMeasure { cpu_seconds, cell_iterations, cells };

// CPU seconds or nx·ny·nz·iterations of one job.
double grid_cost(const GridPoint& grid, CostMeasure measure);

Chart speed_accuracy_chart(const std::vector<SeriesSummary>& series, CostMeasure measure);

}  // namespace gridfree

// SPDX-License-Identifier: GPL-3.0-or-later
// Prior data for `plan --target-rde` (study/target_plan.h): the finished
// series of similar cases in a database.
//
// Similar = a stored series whose job documents have the same case object
// as one of the study's cases (particles, domain, gas, boundaries, probes;
// the case's name does not count) and the same factor levels (convection,
// fwhm_dp, drag, deposition) as one of the study's series, with at least
// one stored uncertainty (its series was extrapolated). Their (Δ*, RDE) of
// every grid are pooled into one fit; their measured CPU seconds over the
// a-priori cost model's (study/cost_model.h) give the cost scale. The
// database is only read.
#pragma once

#include <filesystem>

#include "study/study.h"
#include "study/target_plan.h"

namespace gridfree {

// The fitted model, or the a-priori one when the file does not exist or
// holds no similar series.
RdeModel prior_rde_model(const std::filesystem::path& db_file, const Study& study);

}  // namespace gridfree

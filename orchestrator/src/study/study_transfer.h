// SPDX-License-Identifier: GPL-3.0-or-later
// Transfer methods as a study factor (docs/INTERFACE.md §3, docs/TRANSFER.md).
//
// A level of factors.deposition is a name ("diffusion", "centroid", the
// presets "fm18" and "mfix") or an object that spells a transfer:
//
//   {"name": "cic", "pre_deposition": "trilinear", "sampling": "trilinear"}
//
// with any of pre_deposition, sampling, diffusivity, integration, steps,
// truncation_sigmas, or "preset". An object level is merged over the
// study's numerics.deposition (its own fields win); the series carries its
// name (given, or made from its fields: "pre=trilinear,samp=cell"). Every
// level is parsed with the worker's own rules (parse_deposition), so a
// contradictory level is refused with its JSON path, and two levels that
// give the same expanded transfer are refused as duplicates.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "study/study.h"

namespace gridfree {

// Reads factors.deposition (array at `at`) into study.factors.deposition
// (level names) and study.transfer_levels (object levels by name).
void parse_deposition_levels(const nlohmann::json& levels, const std::string& at, Study& study,
                             ProblemList& problems);

// After the whole study is read: every level parsed as the worker would
// (merged with numerics.deposition), duplicates refused.
void check_deposition_levels(const Study& study, ProblemList& problems);

// The numerics.deposition object of a job of this level and filter width
// (for name levels exactly what studies have always written: job hashes of
// existing studies do not change).
nlohmann::json deposition_document(const Study& study, const std::string& level, double fwhm_dp);

// The expanded transfer of a job's numerics.deposition, as stored in the
// series table (docs/DATABASE.md): "" where a field does not apply
// (integration/diffusivity without a filter), steps 0 unless integration is
// "steps". Throws InputError for a deposition the worker refuses.
TransferColumns transfer_columns(const nlohmann::json& deposition);

}  // namespace gridfree

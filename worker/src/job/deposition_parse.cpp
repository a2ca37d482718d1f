// SPDX-License-Identifier: GPL-3.0-or-later
// numerics.deposition (job/job_spec.h, docs/TRANSFER.md, docs/INTERFACE.md).
//
//   kind            "diffusion" (filtered, grid-independent) | "centroid" (grid-coupled, no filter)
//   preset          "fm18": centroid, cell, seed, steps, 8 steps — the paper's method as the
//                           solver computed it before the transfer options existed;
//                   "mfix": centroid, cell, mfix, steps, 5 steps — what MFiX 2016-1 runs.
//                   A preset fixes every transfer field: giving one beside it is refused.
//   pre_deposition  centroid | trilinear | gaussian              (default trilinear)
//   sampling        cell | trilinear | gaussian                  (default trilinear; gaussian
//                   pre-deposition defaults to gaussian)
//   diffusivity     seed | consistent | mfix                     (default consistent)
//   integration     steps | exact | gaussian                     (default exact;
//                   deposition/filter_integration.h holds the names)
//   steps           backward-Euler steps, integration "steps" only (default 8)
//   truncation_sigmas  gaussian only (default 4)
//
// Refused (each with its JSON pointer): a transfer field with kind
// "centroid"; filter fields (diffusivity, integration, steps) with the
// gaussian pre-deposition, which is not filtered; steps with exact or
// gaussian integration; truncation_sigmas without the gaussian kernel; gaussian
// sampling without the gaussian kernel and trilinear sampling with it.
#include <array>

#include "core/json_fields.h"
#include "deposition/filter_integration.h"
#include "job/job_spec.h"

namespace gridfree {
namespace {

constexpr std::array<const char*, 6> kTransferFields{"pre_deposition", "sampling",  "diffusivity",
                                                      "integration",    "steps",     "truncation_sigmas"};

template <class E, std::size_t N>
E read_enum(const nlohmann::json& dep, const char* key, const std::string& at, ProblemList& problems,
            const std::array<std::pair<const char*, E>, N>& names, E fallback) {
  if (!dep.contains(key)) return fallback;
  const std::string v = read_string(dep, key, at, problems);
  std::string all;
  for (const auto& [name, value] : names) {
    if (v == name) return value;
    all += all.empty() ? name : std::string(", ") + name;
  }
  if (!v.empty()) problems.add(child_pointer(at, key), "'" + v + "' is not one of " + all);
  return fallback;
}

void apply_preset(const std::string& preset, const nlohmann::json& dep, const std::string& at,
                  ProblemList& problems, DepositionSpec& d) {
  for (const char* key : kTransferFields)
    if (dep.contains(key)) problems.add(child_pointer(at, key), "is fixed by preset '" + preset + "'; give one or the other");
  if (dep.contains("kind") && dep["kind"] != "diffusion")
    problems.add(child_pointer(at, "kind"), "preset '" + preset + "' is a diffusion deposition");
  d.pre_deposition = PreDeposition::kCentroid;
  d.sampling = Sampling::kCell;
  d.integration = FilterIntegration::kSteps;
  if (preset == "fm18") {
    d.diffusivity = FilterDiffusivity::kSeed;
    d.steps = 8;
  } else if (preset == "mfix") {
    d.diffusivity = FilterDiffusivity::kMfix;
    d.steps = 5;
  } else {
    problems.add(child_pointer(at, "preset"), "'" + preset + "' is not one of fm18, mfix");
  }
}

}  // namespace

DepositionSpec parse_deposition(const nlohmann::json& dep, const std::string& at, ProblemList& problems) {
  DepositionSpec d;
  if (!dep.is_object()) {
    problems.add(at, "deposition must be an object");
    return d;
  }
  if (dep.contains("preset")) {
    apply_preset(read_string(dep, "preset", at, problems), dep, at, problems, d);
    d.fwhm_dp = read_number(dep, "fwhm_dp", at, problems);
    if (!(d.fwhm_dp > 0)) problems.add(child_pointer(at, "fwhm_dp"), "the filter width must be > 0");
    return d;
  }
  const std::string kind = read_string(dep, "kind", at, problems);
  if (kind == "diffusion") d.kind = DepositionKind::kDiffusion;
  else if (kind == "centroid") d.kind = DepositionKind::kCentroid;
  else if (!kind.empty()) problems.add(child_pointer(at, "kind"), "'" + kind + "' is not one of diffusion, centroid");
  if (d.kind == DepositionKind::kCentroid) {
    d.fwhm_dp = read_number(dep, "fwhm_dp", at, problems, 0.0);
    for (const char* key : kTransferFields)
      if (dep.contains(key))
        problems.add(child_pointer(at, key), "centroid deposition has no filter and uses the particle's cell; remove it");
    d.pre_deposition = PreDeposition::kCentroid;
    d.sampling = Sampling::kCell;
    return d;
  }
  d.fwhm_dp = read_number(dep, "fwhm_dp", at, problems);
  if (!(d.fwhm_dp > 0)) problems.add(child_pointer(at, "fwhm_dp"), "the filter width must be > 0");

  d.pre_deposition = read_enum<PreDeposition, 3>(
      dep, "pre_deposition", at, problems,
      {{{"centroid", PreDeposition::kCentroid}, {"trilinear", PreDeposition::kTrilinear}, {"gaussian", PreDeposition::kGaussian}}},
      PreDeposition::kTrilinear);
  const bool gaussian = d.pre_deposition == PreDeposition::kGaussian;
  d.sampling = read_enum<Sampling, 3>(
      dep, "sampling", at, problems,
      {{{"cell", Sampling::kCell}, {"trilinear", Sampling::kTrilinear}, {"gaussian", Sampling::kGaussian}}},
      gaussian ? Sampling::kGaussian : Sampling::kTrilinear);
  if (d.sampling == Sampling::kGaussian && !gaussian)
    problems.add(child_pointer(at, "sampling"), "gaussian sampling needs pre_deposition 'gaussian'");
  if (d.sampling == Sampling::kTrilinear && gaussian)
    problems.add(child_pointer(at, "sampling"),
                 "with pre_deposition 'gaussian' the sampling is 'gaussian' (its adjoint) or 'cell'");
  d.diffusivity = read_enum<FilterDiffusivity, 3>(
      dep, "diffusivity", at, problems,
      {{{"seed", FilterDiffusivity::kSeed}, {"consistent", FilterDiffusivity::kConsistent}, {"mfix", FilterDiffusivity::kMfix}}},
      FilterDiffusivity::kConsistent);
  if (dep.contains("integration")) {
    const std::string v = read_string(dep, "integration", at, problems);
    if (const auto integration = parse_filter_integration(v)) {
      d.integration = *integration;
    } else if (!v.empty()) {
      std::string all;
      for (const auto& n : filter_integration_names()) all += (all.empty() ? "" : ", ") + std::string(n.name);
      problems.add(child_pointer(at, "integration"), "'" + v + "' is not one of " + all);
    }
  }
  if (dep.contains("steps")) {
    const std::int64_t steps = read_integer(dep, "steps", at, problems);
    if (d.integration != FilterIntegration::kSteps)
      problems.add(child_pointer(at, "steps"), "only with integration 'steps' (exact and gaussian integration have no steps)");
    else if (steps < 1 || steps > 100000) problems.add(child_pointer(at, "steps"), "must be from 1 to 100000");
    else d.steps = static_cast<int>(steps);
  }
  if (gaussian) {
    for (const char* key : {"diffusivity", "integration", "steps"})
      if (dep.contains(key))
        problems.add(child_pointer(at, key), "the gaussian pre-deposition is the whole kernel: no filter follows it");
    d.truncation_sigmas = read_number(dep, "truncation_sigmas", at, problems, 4.0);
    if (!(d.truncation_sigmas >= 2 && d.truncation_sigmas <= 8))
      problems.add(child_pointer(at, "truncation_sigmas"), "must be from 2 to 8");
  } else if (dep.contains("truncation_sigmas")) {
    problems.add(child_pointer(at, "truncation_sigmas"), "only with pre_deposition 'gaussian'");
  }
  return d;
}

nlohmann::json deposition_json(const DepositionSpec& d, const nlohmann::json& given) {
  nlohmann::json j{{"kind", std::string(deposition_kind_name(d.kind))}};
  if (d.kind == DepositionKind::kCentroid) {
    if (given.is_object() && given.contains("fwhm_dp")) j["fwhm_dp"] = given["fwhm_dp"];
    return j;
  }
  j["fwhm_dp"] = d.fwhm_dp;
  j["pre_deposition"] = std::string(pre_deposition_name(d.pre_deposition));
  j["sampling"] = std::string(sampling_name(d.sampling));
  if (d.pre_deposition == PreDeposition::kGaussian) {
    j["truncation_sigmas"] = d.truncation_sigmas;
    return j;
  }
  j["diffusivity"] = std::string(filter_diffusivity_name(d.diffusivity));
  j["integration"] = std::string(filter_integration_name(d.integration));
  if (d.integration == FilterIntegration::kSteps) j["steps"] = d.steps;
  return j;
}

}  // namespace gridfree

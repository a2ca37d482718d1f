// SPDX-License-Identifier: GPL-3.0-or-later
// The job of docs/INTERFACE.md §2 (the paper's PC1 baseline), for the job tests.
#pragma once

#include <nlohmann/json.hpp>

namespace gridfree::test {

inline nlohmann::json contract_job() {
  return nlohmann::json::parse(R"({
    "schema": "gridfree/job/1",
    "case": {
      "name": "PC1",
      "domain_dp": [30, 200, 10],
      "particle_diameter_cm": 0.01,
      "gas": {"density_g_cm3": 1e-3, "viscosity_g_cm_s": 2e-4},
      "gravity_cm_s2": [0, 0, 0],
      "boundaries": {
        "x": "periodic", "z": "periodic",
        "y_low":  {"type": "mass_inflow", "superficial_velocity_cm_s": 20.0},
        "y_high": {"type": "pressure_outflow", "pressure_dyn_cm2": 0.0}
      },
      "particles": {"generator": {"kind": "bursting_bubble", "seed": 1}},
      "particle_velocity": {"thermal_cm_s": 0.0, "seed": 0},
      "probes": {"pressure_drop": {"y1_dp": 4, "y2_dp": 104}}
    },
    "numerics": {
      "grid": {"cells": [30, 200, 10]},
      "convection": "superbee",
      "drag": "bvk",
      "deposition": {"kind": "diffusion", "fwhm_dp": 6},
      "tolerances": {"linear": 1e-8, "filter": 1e-10, "steady": 1e-5},
      "max_iterations": 20000
    }
  })");
}

}  // namespace gridfree::test

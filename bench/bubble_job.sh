# SPDX-License-Identifier: GPL-3.0-or-later
# Shared by the transfer benchmarks (source it): the bursting-bubble
# baseline job (PC1, superbee, bvk) on one grid with a given
# numerics.deposition object, and the machine line every benchmark prints.

# write_bubble_job FILE NX NY NZ DEPOSITION_JSON
write_bubble_job() {
  cat >"$1" <<JSON
{
  "schema": "gridfree/job/1",
  "case": {
    "name": "PC1", "domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
    "gas": {"density_g_cm3": 1e-3, "viscosity_g_cm_s": 2e-4},
    "gravity_cm_s2": [0, 0, 0],
    "boundaries": {"x": "periodic", "z": "periodic",
      "y_low": {"type": "mass_inflow", "superficial_velocity_cm_s": 20.0},
      "y_high": {"type": "pressure_outflow", "pressure_dyn_cm2": 0.0}},
    "particles": {"generator": {"kind": "bursting_bubble", "seed": 1}},
    "probes": {"pressure_drop": {"y1_dp": 4, "y2_dp": 104}}
  },
  "numerics": {
    "grid": {"cells": [$2, $3, $4]}, "convection": "superbee", "drag": "bvk",
    "deposition": $5,
    "tolerances": {"linear": 1e-8, "filter": 1e-10, "steady": 1e-5},
    "max_iterations": 20000
  }
}
JSON
}

machine_line() {
  echo "machine: $(nproc) cores, $(uname -m), $(date -u +%Y-%m-%dT%H:%MZ), load $(cut -d' ' -f1-3 /proc/loadavg)"
}

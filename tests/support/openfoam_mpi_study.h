// SPDX-License-Identifier: GPL-3.0-or-later
// An OpenFOAM study whose finest grid runs on 2 MPI ranks (docs/EXTERNAL.md
// "Cores"): the shipped lid-driven cavity (studies/external/cavity, icoFoam)
// with two more rendered files — system/decomposeParDict (@@cores@@
// subdomains, method simple) and an Allrun that decomposes and runs
// `mpirun -np @@cores@@ icoFoam -parallel` when it has more than one core —
// on N = 10, 14, 20 for 0.05 s (5–10 time steps), every pressure solve
// to its tolerance (relTol 0: the shipped 0.05 leaves the non-final PISO
// corrector's answer to the preconditioner, which decomposing changes —
// 1e-4 relative in mean |U|² after 10 steps). With the cores rule
// max(1, cells / 200) the 20² grid gets 2 cores (cells / 200 = 2), the
// others one (0.5, 0.98). Without the rule every grid runs serially, which
// is the reference the decomposed run is compared with.
#pragma once

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "project_paths.h"

namespace gridfree::test_support {

inline constexpr const char* kMpiCoresRule = "max(1, cells / 200)";
inline constexpr int kMpiFinestN = 20;

// Writes <dir>/cavity (the template) and <dir>/<name>.json; returns the study file.
inline std::filesystem::path write_openfoam_mpi_study(const std::filesystem::path& dir, const std::string& name,
                                                      bool cores_rule) {
  namespace fs = std::filesystem;
  const fs::path tpl = dir / "cavity";
  if (!fs::exists(tpl)) {
    fs::copy(kSourceDir / "studies/external/cavity", tpl, fs::copy_options::recursive);
    std::ofstream(tpl / "system/decomposeParDict")
        << "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
           "numberOfSubdomains @@cores@@;\nmethod simple;\n"
           "simpleCoeffs { n (@@cores@@ 1 1); delta 0.001; }\n";
    std::stringstream solution;
    solution << std::ifstream(tpl / "system/fvSolution").rdbuf();
    std::ofstream(tpl / "system/fvSolution")
        << std::regex_replace(solution.str(), std::regex(R"(relTol\s+[0-9.eE+-]+;)"), "relTol 0;");
    std::ofstream(tpl / "Allrun") << "#!/bin/sh\nset -e\nblockMesh > log.blockMesh 2>&1\n"
                                     "if [ @@cores@@ -gt 1 ]; then\n"
                                     "  decomposePar > log.decomposePar 2>&1\n"
                                     "  mpirun --allow-run-as-root --oversubscribe -np @@cores@@ icoFoam -parallel "
                                     "> log.icoFoam 2>&1\n"
                                     "else\n  icoFoam > log.icoFoam 2>&1\nfi\n";
  }
  nlohmann::json doc = {
      {"schema", "gridfree/study/1"},
      {"name", name},
      {"cases",
       {{"cavity",
         {{"external",
           {{"template", "cavity"},
            {"render", {"system/blockMeshDict", "system/controlDict", "system/decomposeParDict", "Allrun"}},
            {"variables", {{"dt", "0.1 / N"}, {"end_time", "0.05"}}},
            {"h", "0.1 / N"},
            {"cells", "N ^ 2"},
            {"setup", {"export WM_PROJECT_DIR=/usr/share/openfoam"}},
            {"command", {"sh", "Allrun"}},
            {"version", "openfoam v1912"},
            {"collect",
             {{"quantities",
               {{"mean_u2",
                 {{"units", "m^2/s^2"},
                  {"description", "volume average of |U|^2"},
                  {"file", "postProcessing/meanU2/0/volFieldValue.dat"},
                  {"column", 1}}}}},
              {"failure_patterns", {"FOAM FATAL"}}}}}}}}}},
      {"grids", {{"variables", {{"N", {10, 14, kMpiFinestN}}}}}},
      {"timeout_s", 300}};
  if (cores_rule) doc["cores"] = kMpiCoresRule;
  const fs::path file = dir / (name + ".json");
  std::ofstream(file) << doc.dump(2);
  return file;
}

}  // namespace gridfree::test_support

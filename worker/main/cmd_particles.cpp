// SPDX-License-Identifier: GPL-3.0-or-later
// gridfree-worker particles SPEC.json [-o FILE.csv] [--stats | --stats-json]
//
// Generates a seeded configuration or converts a particle file (e.g. MFiX
// particle_input.dat or a LAMMPS dump → CSV), docs/INTERFACE.md §2, and
// with --stats prints the bed's structure (particles/bed_structure.h) to
// stdout, as text or (--stats-json) JSON. The spec is validated first;
// any problem exits 2 naming its JSON path and nothing is written. The
// output is written to a temporary file beside FILE and renamed over it, so
// FILE is either the complete new configuration or untouched.
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

#include <spdlog/spdlog.h>
#include <unistd.h>

#include "commands.h"
#include "output_path.h"
#include "core/exit_codes.h"
#include "core/input_error.h"
#include "job/job_spec.h"
#include "job/particles_spec.h"
#include "particles/bed_structure.h"
#include "particles/particle_io.h"

namespace gridfree::worker_cli {
namespace {

struct ParticlesOptions {
  std::string spec;
  std::string output;
  std::string format = "csv";
  bool stats = false;
  bool stats_json = false;
};

void write_atomically(const std::filesystem::path& target, const ParticleSet& set, const std::string& format) {
  std::filesystem::path temp = target;
  temp += ".tmp-" + std::to_string(::getpid());
  try {
    if (format == "mfix") write_mfix(temp, set);
    else write_csv(temp, set);
    std::filesystem::rename(temp, target);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw;
  }
}

int run_particles(const ParticlesOptions& o) {
  // 1. Check where the output goes, then read and validate the spec.
  if (o.output.empty() && !o.stats && !o.stats_json)
    throw InputError("-o", "give an output file (-o FILE), --stats or --stats-json");
  if (!o.output.empty()) check_output_path("-o", o.output);
  const std::filesystem::path spec_file(o.spec);
  const nlohmann::json doc = read_json_file(spec_file);
  const CaseSpec c = parse_particles_spec(doc, spec_file.has_parent_path() ? spec_file.parent_path() : ".");

  // 2. Generate or read (and check) the particles.
  const GeneratedParticles out = load_particles_with_report(c.particles, c);

  // 3. Report per region, then write.
  spdlog::info("{} particles", out.set.particles.size());
  for (const RegionReport& r : out.regions)
    spdlog::info("  {:<18} {:>9} particles  solids fraction {:.5f} (target {:.5f}, volume {:.6g} cm3)", r.name,
                 r.count, r.solids_fraction, r.target_fraction, r.volume_cm3);
  if (!o.output.empty()) {
    write_atomically(o.output, out.set, o.format);
    spdlog::info("wrote {}", o.output);
  }
  if (o.stats || o.stats_json) {
    const BedStructure s = bed_structure(out.set.particles, c.domain_cm(), {c.periodic(0), c.periodic(1), c.periodic(2)});
    const std::string text = o.stats_json ? to_json(s).dump(1) + "\n" : to_text(s);
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
  }
  return to_int(ExitCode::kOk);
}

}  // namespace

void add_particles_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ParticlesOptions>();
  auto* sub = app.add_subcommand("particles", "Generate a particle configuration or convert a particle file to CSV");
  sub->add_option("SPEC", options->spec, "JSON spec: domain_dp, particle_diameter_cm, and generator or file+format")
      ->required();
  sub->add_option("-o,--output", options->output, "Output file (CSV x,y,z,d[,u,v,w], cm)");
  sub->add_flag("--stats", options->stats,
                "Print the bed's structure: largest structure factor, g(r), solids fraction profile and histogram");
  sub->add_flag("--stats-json", options->stats_json, "The same as JSON");
  sub->add_option("--format", options->format, "Output format")->check(CLI::IsMember({"csv", "mfix"}));
  sub->callback([options, &exit_code] { exit_code = run_particles(*options); });
}

}  // namespace gridfree::worker_cli

// SPDX-License-Identifier: GPL-3.0-or-later
// The bed-structure "About this case" section (see bed_about.h).
#include "report/bed_about.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace gridfree {
namespace {

std::string format(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// The number at a JSON pointer, if it is one.
std::optional<double> value_at(const nlohmann::json& j, const char* pointer) {
  const auto p = nlohmann::json::json_pointer(pointer);
  if (!j.contains(p) || !j.at(p).is_number()) return std::nullopt;
  const double v = j.at(p).get<double>();
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// "a" or "a – b" over the instances (each formatted with f), "?" when none has it.
std::string range(const std::vector<const nlohmann::json*>& beds, const char* pointer, const char* f) {
  std::optional<double> lo, hi;
  for (const auto* b : beds)
    if (const auto v = value_at(*b, pointer)) {
      lo = lo ? std::min(*lo, *v) : *v;
      hi = hi ? std::max(*hi, *v) : *v;
    }
  if (!lo) return "?";
  const std::string a = format(f, *lo), b = format(f, *hi);
  return a == b ? a : a + " – " + b;
}

// "0.0049 (y, period 0.98 d)": the peak's range, and the axis and period of
// the largest instance's.
std::string peak(const std::vector<const nlohmann::json*>& beds, const std::string& key) {
  const nlohmann::json* largest = nullptr;
  double best = -1;
  for (const auto* b : beds)
    if (const auto v = value_at(*b, ("/" + key + "/s_over_n").c_str()); v && *v > best) {
      best = *v;
      largest = b;
    }
  std::string out = range(beds, ("/" + key + "/s_over_n").c_str(), "%.2g");
  if (!largest) return out;
  const auto& p = largest->at(key);
  out += " (" + std::string(beds.size() > 1 ? "largest: " : "") + p.value("axis", std::string("?"));
  if (const auto period = value_at(p, "/period_dp")) out += ", period " + format("%.2f", *period) + " d";
  return out + ")";
}

std::string ordered_words(const std::vector<const nlohmann::json*>& beds) {
  std::size_t ordered = 0, known = 0;
  // The worker's own flag (particles/bed_summary.h), else the same rule here.
  for (const auto* b : beds) {
    if (b->contains("ordered") && b->at("ordered").is_boolean()) {
      ++known;
      ordered += b->at("ordered").get<bool>();
    } else if (const auto v = value_at(*b, "/largest_structure_factor_core/s_over_n")) {
      ++known;
      ordered += *v >= kOrderedBedPeak;
    }
  }
  if (known == 0) return "order not measured";
  if (beds.size() == 1) return ordered ? "ORDERED (core peak ≥ 0.05 N)" : "random (core peak < 0.05 N)";
  if (ordered == 0) return "random in every instance (core peak < 0.05 N)";
  return "ORDERED in " + std::to_string(ordered) + " of " + std::to_string(known) + " instances (core peak ≥ 0.05 N)";
}

}  // namespace

std::string bed_line(const std::vector<const nlohmann::json*>& b) {
  std::string out = "N " + range(b, "/particles", "%.0f") + ", ε_s " + range(b, "/solids_fraction", "%.3f") +
                    " (bed height " + range(b, "/height_dp", "%.1f") + " d); largest S/N " +
                    peak(b, "largest_structure_factor") + ", in the core " + peak(b, "largest_structure_factor_core") +
                    ": " + ordered_words(b) + "; g(r) contact peak " + range(b, "/rdf/contact_peak", "%.2f") + " at " +
                    range(b, "/rdf/contact_peak_r_dp", "%.2f") + " d, g(√3 d) " + range(b, "/rdf/at_sqrt3_dp", "%.2f") +
                    ", g(2 d) " + range(b, "/rdf/at_2_dp", "%.2f");
  bool has_profile = false;
  for (const auto* x : b) has_profile = has_profile || value_at(*x, "/solids_fraction_y/min").has_value();
  if (has_profile) {
    out += "; ε_s(y) " + range(b, "/solids_fraction_y/min", "%.3f") + " to " + range(b, "/solids_fraction_y/max", "%.3f") +
           " over y " + range(b, "/solids_fraction_y/from_dp", "%.0f") + " to " +
           range(b, "/solids_fraction_y/to_dp", "%.0f") + " d";
  }
  out += "; local ε_s " + range(b, "/local_solids_fraction/mean", "%.3f") + " ± " +
         range(b, "/local_solids_fraction/std", "%.3f") + ".";
  return out;
}

std::optional<AboutSection> bed_about_section(const std::vector<std::string>& cases,
                                              const std::map<std::string, nlohmann::json>& beds,
                                              const std::map<std::string, std::vector<std::string>>& ensembles) {
  if (beds.empty()) return std::nullopt;
  AboutSection s;
  s.title = "About this case: bed structure";
  s.paragraphs.push_back(
      "Measured by the worker on the particles each case solves (docs/PARTICLES.md \"Structure\"), one line per "
      "case and one per ensemble (ranges over its instances). S/N is the largest structure factor |Σ exp(i k·x)|²/N "
      "over the axis-aligned wave vectors of periods 0.5 to 2 d, with its axis and period: a random packing gives S/N "
      "of order 1/N, a crystal of order 1; a peak of 0.05 N or more in the core (the particles at least 3 d inside "
      "the bed) is flagged ORDERED, and the peak over all particles also sees the layering at walls and the floor. "
      "g(r) of a random dense packing has a contact peak near 1 d and g above 1 at both √3 d and 2 d (a crystal: "
      "sharp shells with g near 0 between them). ε_s: the solid volume over the domain below the highest sphere's "
      "top; ε_s(y): the smallest and largest one-diameter slab at least 2 d inside the bed; local ε_s: cubes of "
      "about 3 d, mean ± standard deviation.");
  std::map<std::string, std::string> ensemble_of;
  for (const auto& [name, members] : ensembles)
    for (const auto& m : members) ensemble_of[m] = name;
  std::set<std::string> done;
  std::vector<std::string> without;
  for (const auto& c : cases) {
    if (!done.insert(c).second) continue;
    const auto e = ensemble_of.find(c);
    if (e == ensemble_of.end()) {
      const auto b = beds.find(c);
      if (b == beds.end()) without.push_back(c);
      else s.paragraphs.push_back(c + ": " + bed_line({&b->second}));
      continue;
    }
    // The whole ensemble at its first instance.
    std::vector<const nlohmann::json*> instances;
    const auto& members = ensembles.at(e->second);
    for (const auto& m : members) {
      done.insert(m);
      if (const auto b = beds.find(m); b != beds.end()) instances.push_back(&b->second);
    }
    if (instances.empty()) {
      without.push_back("ensemble " + e->second);
      continue;
    }
    std::string head = "ensemble " + e->second + " (" + std::to_string(members.size()) + " instances";
    if (instances.size() < members.size()) head += ", " + std::to_string(instances.size()) + " measured";
    s.paragraphs.push_back(head + "): " + bed_line(instances));
  }
  if (!without.empty()) {
    std::string list;
    for (const auto& w : without) list += (list.empty() ? "" : ", ") + w;
    s.paragraphs.push_back("No bed summary (a continuum bed, no finished job yet, or results from before the summary): " +
                           list + ".");
  }
  return s;
}

}  // namespace gridfree

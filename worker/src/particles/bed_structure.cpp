// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/bed_structure.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <iomanip>
#include <sstream>

#include "particles/cell_list.h"

namespace gridfree {
namespace {

constexpr double kRdfRangeDp = 3.0;
constexpr double kHistogramBin = 0.02;

double coord(const Particle& p, int a) { return a == 0 ? p.x : (a == 1 ? p.y : p.z); }

// Linear interpolation of g between bin centres.
double g_at(const RadialDistribution& r, double x_dp) {
  const double f = x_dp / r.bin_dp - 0.5;
  const auto i = static_cast<std::size_t>(std::clamp(std::floor(f), 0.0, static_cast<double>(r.g.size() - 2)));
  const double t = std::clamp(f - static_cast<double>(i), 0.0, 1.0);
  return (1 - t) * r.g[i] + t * r.g[i + 1];
}

// Volume of a sphere (radius r, centre height c) below height t.
double cap_below(double r, double c, double t) {
  const double u = std::clamp(t - c, -r, r);
  return std::numbers::pi * (r * r * u - u * u * u / 3 + 2 * r * r * r / 3);
}

// The core: the particles at least min(margin, extent / 4) inside the
// particles' extent on every non-periodic axis, and that window.
struct Core {
  std::vector<Particle> particles;
  std::array<double, 3> lo{}, hi{};
};

Core core_of(const std::vector<Particle>& particles, const std::array<double, 3>& length,
             const std::array<bool, 3>& periodic, double margin) {
  Core c;
  for (int a = 0; a < 3; ++a) {
    if (periodic[a]) {
      c.lo[a] = 0;
      c.hi[a] = length[a];
      continue;
    }
    double lo = particles.empty() ? 0 : coord(particles[0], a), hi = lo;
    for (const Particle& p : particles) {
      lo = std::min(lo, coord(p, a));
      hi = std::max(hi, coord(p, a));
    }
    const double m = std::min(margin, 0.25 * (hi - lo));
    c.lo[a] = lo + m;
    c.hi[a] = hi - m;
  }
  for (const Particle& p : particles) {
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && coord(p, a) >= c.lo[a] && coord(p, a) <= c.hi[a];
    if (inside) c.particles.push_back(p);
  }
  return c;
}

StructurePeak largest_of(const std::array<StructurePeak, 3>& peaks) {
  StructurePeak best = peaks[0];
  for (const StructurePeak& p : peaks)
    if (p.s_over_n > best.s_over_n) best = p;
  return best;
}

}  // namespace

std::array<StructurePeak, 3> largest_structure_peaks(const std::vector<Particle>& particles,
                                                     const std::array<double, 3>& length_cm, double d,
                                                     const StructureOptions& options, const PeakWindow* window) {
  std::array<StructurePeak, 3> out{};
  const double n = static_cast<double>(particles.size());
  for (int a = 0; a < 3; ++a) {
    out[a].axis = a;
    const double l = length_cm[a];
    const int m_lo = std::max(1, static_cast<int>(std::ceil(l / (options.max_period_dp * d))));
    const int m_hi = static_cast<int>(std::floor(l / (options.min_period_dp * d)));
    if (m_hi < m_lo || particles.empty()) continue;
    std::vector<std::complex<double>> sum(static_cast<std::size_t>(m_hi - m_lo + 1));
    for (const Particle& p : particles) {
      const double theta = 2 * std::numbers::pi * coord(p, a) / l;
      const std::complex<double> step = std::polar(1.0, theta);
      std::complex<double> z;
      for (int m = m_lo; m <= m_hi; ++m) {
        // Exact every 32 modes, the recurrence in between (error ~1e-14).
        z = (m - m_lo) % 32 == 0 ? std::polar(1.0, theta * m) : z * step;
        sum[static_cast<std::size_t>(m - m_lo)] += z;
      }
    }
    for (int m = m_lo; m <= m_hi; ++m) {
      std::complex<double> z = sum[static_cast<std::size_t>(m - m_lo)];
      if (window != nullptr && !window->periodic[a]) {
        // Minus N times the mean of exp(ikx) over x uniform in [lo, hi].
        const double k = 2 * std::numbers::pi * m / l, w = window->hi[a] - window->lo[a];
        if (w > 0)
          z -= n * (std::polar(1.0, k * window->hi[a]) - std::polar(1.0, k * window->lo[a])) /
               std::complex<double>(0, k * w);
      }
      const double s = std::norm(z) / n / n;
      if (s > out[a].s_over_n) out[a] = {a, m, l / m / d, s};
    }
  }
  return out;
}

RadialDistribution radial_distribution(const std::vector<Particle>& particles, const std::array<double, 3>& length_cm,
                                       const std::array<bool, 3>& periodic, double d) {
  RadialDistribution r;
  r.g.assign(static_cast<std::size_t>(std::lround(kRdfRangeDp / r.bin_dp)), 0.0);
  if (particles.empty()) return r;
  const double range = kRdfRangeDp * d;
  // The core: at least `range` inside the particles' extent on non-periodic axes.
  std::array<double, 3> lo{}, hi{};
  double volume = 1;
  for (int a = 0; a < 3; ++a) {
    if (periodic[a]) {
      lo[a] = 0;
      hi[a] = length_cm[a];
    } else {
      double mn = coord(particles[0], a), mx = mn;
      for (const Particle& p : particles) {
        mn = std::min(mn, coord(p, a));
        mx = std::max(mx, coord(p, a));
      }
      lo[a] = mn + range;
      hi[a] = mx - range;
    }
    volume *= std::max(0.0, hi[a] - lo[a]);
  }
  if (!(volume > 0)) return r;
  const auto in_core = [&](const Particle& p) {
    for (int a = 0; a < 3; ++a)
      if (!periodic[a] && (coord(p, a) < lo[a] || coord(p, a) > hi[a])) return false;
    return true;
  };
  CellList cells(length_cm, periodic, range);
  std::vector<Vec3> x(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    x[i] = {particles[i].x, particles[i].y, particles[i].z};
    cells.insert(static_cast<std::uint32_t>(i), x[i]);
  }
  std::vector<double> count(r.g.size(), 0.0);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!in_core(particles[i])) continue;
    ++r.reference_particles;
    cells.for_each_near(x[i], [&](std::uint32_t j) {
      if (j == i) return;
      const double dist = std::sqrt(cells.distance_squared(x[i], x[j])) / d;
      const auto bin = static_cast<std::size_t>(dist / r.bin_dp);
      if (bin < count.size()) count[bin] += 1;
    });
  }
  const double density = static_cast<double>(r.reference_particles) / (volume / (d * d * d));  // per d³
  for (std::size_t k = 0; k < r.g.size(); ++k) {
    const double a = r.bin_dp * static_cast<double>(k), b = a + r.bin_dp;
    const double shell = 4.0 / 3.0 * std::numbers::pi * (b * b * b - a * a * a);
    r.g[k] = r.reference_particles > 0 ? count[k] / (static_cast<double>(r.reference_particles) * density * shell) : 0;
  }
  for (std::size_t k = 0; (static_cast<double>(k) + 0.5) * r.bin_dp < 1.1; ++k)
    if (r.g[k] > r.contact_peak) {
      r.contact_peak = r.g[k];
      r.contact_peak_r_dp = (static_cast<double>(k) + 0.5) * r.bin_dp;
    }
  r.at_sqrt3 = g_at(r, std::sqrt(3.0));
  r.at_2 = g_at(r, 2.0);
  r.dip_between = std::min(r.at_sqrt3, r.at_2);
  for (std::size_t k = 0; k < r.g.size(); ++k) {
    const double c = (static_cast<double>(k) + 0.5) * r.bin_dp;
    if (c > std::sqrt(3.0) && c < 2.0) r.dip_between = std::min(r.dip_between, r.g[k]);
  }
  return r;
}

std::vector<double> solids_fraction_profile_y(const std::vector<Particle>& particles,
                                              const std::array<double, 3>& length_cm, double d) {
  const auto bins = static_cast<std::size_t>(std::ceil(length_cm[1] / d - 1e-9));
  std::vector<double> volume(bins, 0.0);
  for (const Particle& p : particles) {
    const double r = 0.5 * p.d;
    const auto first = static_cast<std::size_t>(std::max(0.0, std::floor((p.y - r) / d)));
    for (std::size_t b = first; b < bins && static_cast<double>(b) * d < p.y + r; ++b) {
      const double y0 = static_cast<double>(b) * d, y1 = std::min(length_cm[1], y0 + d);
      volume[b] += cap_below(r, p.y, y1) - cap_below(r, p.y, y0);
    }
  }
  for (std::size_t b = 0; b < bins; ++b) {
    const double y0 = static_cast<double>(b) * d, y1 = std::min(length_cm[1], y0 + d);
    volume[b] /= length_cm[0] * length_cm[2] * (y1 - y0);
  }
  return volume;
}

BedStructure bed_structure(const std::vector<Particle>& particles, const std::array<double, 3>& length_cm,
                           const std::array<bool, 3>& periodic, const StructureOptions& options) {
  BedStructure s;
  s.particles = particles.size();
  if (particles.empty()) return s;
  const double d = particles[0].d;
  s.diameter_cm = d;
  s.largest_peak_per_axis = largest_structure_peaks(particles, length_cm, d, options);
  s.largest_peak = largest_of(s.largest_peak_per_axis);
  const Core core = core_of(particles, length_cm, periodic, kRdfRangeDp * d);
  s.core_particles = core.particles.size();
  const PeakWindow window{periodic, core.lo, core.hi};
  s.largest_core_peak_per_axis = largest_structure_peaks(core.particles, length_cm, d, options, &window);
  s.largest_core_peak = largest_of(s.largest_core_peak_per_axis);
  s.rdf = radial_distribution(particles, length_cm, periodic, d);
  s.solids_fraction_y = solids_fraction_profile_y(particles, length_cm, d);

  // Local ε_s in cubes of side ≈ 3 d below the highest centre.
  std::array<int, 3> n{};
  std::array<double, 3> side{};
  for (int a = 0; a < 3; ++a) {
    n[a] = std::max(1, static_cast<int>(std::lround(length_cm[a] / (s.local_cube_dp * d))));
    side[a] = length_cm[a] / n[a];
  }
  double top = 0;
  for (const Particle& p : particles) top = std::max(top, p.y);
  const int layers = std::min(n[1], static_cast<int>(std::floor(top / side[1])));
  if (layers > 0) {
    std::vector<double> filled(static_cast<std::size_t>(n[0]) * layers * n[2], 0.0);
    const double vp = std::numbers::pi * d * d * d / 6;
    for (const Particle& p : particles) {
      const int i = std::clamp(static_cast<int>(p.x / side[0]), 0, n[0] - 1);
      const int j = static_cast<int>(p.y / side[1]);
      const int k = std::clamp(static_cast<int>(p.z / side[2]), 0, n[2] - 1);
      if (j < 0 || j >= layers) continue;
      filled[(static_cast<std::size_t>(k) * layers + j) * n[0] + i] += vp;
    }
    const double cube = side[0] * side[1] * side[2];
    double sum = 0, sum2 = 0;
    for (double v : filled) {
      const double f = v / cube;
      const auto bin = static_cast<std::size_t>(f / kHistogramBin);
      if (bin >= s.local_histogram.size()) s.local_histogram.resize(bin + 1, 0);
      ++s.local_histogram[bin];
      sum += f;
      sum2 += f * f;
    }
    s.local_cubes = filled.size();
    const double m = static_cast<double>(filled.size());
    s.local_mean = sum / m;
    s.local_std = std::sqrt(std::max(0.0, sum2 / m - s.local_mean * s.local_mean));
  }
  return s;
}

nlohmann::json to_json(const BedStructure& s) {
  const auto peak = [](const StructurePeak& p) {
    return nlohmann::json{{"axis", std::string(1, "xyz"[p.axis])}, {"m", p.m}, {"period_dp", p.period_dp},
                          {"s_over_n", p.s_over_n}};
  };
  nlohmann::json j;
  j["particles"] = s.particles;
  j["largest_structure_factor"] = peak(s.largest_peak);
  j["largest_structure_factor_per_axis"] = nlohmann::json::array();
  for (const StructurePeak& p : s.largest_peak_per_axis) j["largest_structure_factor_per_axis"].push_back(peak(p));
  j["core_particles"] = s.core_particles;
  j["largest_structure_factor_core"] = peak(s.largest_core_peak);
  j["largest_structure_factor_core_per_axis"] = nlohmann::json::array();
  for (const StructurePeak& p : s.largest_core_peak_per_axis)
    j["largest_structure_factor_core_per_axis"].push_back(peak(p));
  j["rdf"] = {{"bin_dp", s.rdf.bin_dp},
              {"reference_particles", s.rdf.reference_particles},
              {"contact_peak", s.rdf.contact_peak},
              {"contact_peak_r_dp", s.rdf.contact_peak_r_dp},
              {"at_sqrt3_dp", s.rdf.at_sqrt3},
              {"at_2_dp", s.rdf.at_2},
              {"dip_between", s.rdf.dip_between},
              {"g", s.rdf.g}};
  j["solids_fraction_y"] = {{"bin_dp", 1}, {"values", s.solids_fraction_y}};
  j["local_solids_fraction"] = {{"cube_dp", s.local_cube_dp}, {"cubes", s.local_cubes}, {"mean", s.local_mean},
                                {"std", s.local_std}, {"histogram_bin", kHistogramBin},
                                {"histogram", s.local_histogram}};
  return j;
}

std::string to_text(const BedStructure& s) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(4);
  os << "structure of " << s.particles << " particles\n";
  os << "  largest S(k)/N per axis (periods 0.5-2 d):";
  for (const StructurePeak& p : s.largest_peak_per_axis)
    os << "  " << "xyz"[p.axis] << " " << p.s_over_n << " at " << p.period_dp << " d";
  os << "\n  the same in the core (" << s.core_particles << " particles >= min(3 d, extent/4) inside):";
  for (const StructurePeak& p : s.largest_core_peak_per_axis)
    os << "  " << "xyz"[p.axis] << " " << p.s_over_n << " at " << p.period_dp << " d";
  os << "\n  g(r): contact peak " << s.rdf.contact_peak << " at " << s.rdf.contact_peak_r_dp << " d; g(sqrt3 d) "
     << s.rdf.at_sqrt3 << ", g(2 d) " << s.rdf.at_2 << ", lowest between " << s.rdf.dip_between << " ("
     << s.rdf.reference_particles << " reference particles)\n";
  os << "  local solids fraction (" << s.local_cubes << " cubes of ~" << s.local_cube_dp << " d): mean "
     << s.local_mean << ", std " << s.local_std << "\n";
  os << "  solids fraction per 1-d slab in y:";
  for (std::size_t i = 0; i < s.solids_fraction_y.size(); ++i) {
    if (i % 10 == 0) os << "\n   " << (i < 10 ? "  " : (i < 100 ? " " : "")) << i << ":";
    os << " " << std::setprecision(3) << s.solids_fraction_y[i];
  }
  os << "\n";
  return os.str();
}

}  // namespace gridfree

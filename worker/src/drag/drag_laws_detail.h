// SPDX-License-Identifier: GPL-3.0-or-later
// The individual drag laws behind drag_coefficient() (PHYSICS.md §4).
//
// Each function returns D (g/(cm^3 s)) with β = ε_s D (MFiX Model A), for a
// DragState with 0 < ε_g ≤ 1, slip ≥ 0, d > 0, ρ_g > 0, μ_g > 0. Every law is
// finite and positive at slip = 0 (its Re → 0 limit), never 0/0.
//
// MFiX convention: MFiX's drag routines (model/drag_gs.f) return "DgA" and
// form F_gs = DgA · EP_SM for Model A; DgA is exactly our D. MFiX sets
// DgA = 0 when Re = 0 (no slip: the force is zero anyway); we return the
// limit instead, because D multiplies the unknown velocity implicitly.
#pragma once

#include "drag/drag_law.h"

namespace gridfree::drag_detail {

// Re_s = ε_g ρ_g |u − v| d / μ_g.
double particle_reynolds(const DragState& s);

// Solids fraction φ = 1 − ε_g, clamped to ≥ 0 (ε_g may exceed 1 by round-off).
double solids_fraction(const DragState& s);

// Wen & Yu: D = (3/4) C_d ρ_g ε_g |u−v| ε_g^(−2.65) / d.
double wen_yu(const DragState& s);
// Ergun: D = 150 ε_s μ_g / (ε_g d²) + 1.75 ρ_g |u−v| / d.
double ergun(const DragState& s);
// Gidaspow: Ergun for ε_g ≤ 0.8, Wen & Yu above.
double gidaspow(const DragState& s);
// Lathouwers & Bellan blend of Ergun and Wen & Yu around ε_g = 0.8.
double gidaspow_blend(const DragState& s);
// Beetstra, van der Hoef & Kuipers (2007), monodisperse.
double bvk(const DragState& s);
// Hill, Koch & Ladd as extended by Benyahia, Syamlal & O'Brien (2006).
double hkl(const DragState& s);
// Syamlal & O'Brien (1988), default constants c1 = 0.8, d1 = 2.65.
double syamlal_obrien(const DragState& s);

// The dimensionless HKL pieces, exposed for tests and the docs table.
struct HklTerms {
  double f0 = 0, f1 = 0, f2 = 0, f3 = 0;  // F0..F3 at φ (unset ones stay 0)
  double re_t1 = 0, re_t2 = 0;            // transition Re_h
};
HklTerms hkl_terms(double phi);
// F(φ, Re_h) of HKL, so that D = 18 μ_g ε_g² F / d².
double hkl_f(double phi, double re_h);
// F(φ, Re_s) of BVK, so that D = 18 μ_g ε_g F / d².
double bvk_f(double phi, double re_s);

}  // namespace gridfree::drag_detail

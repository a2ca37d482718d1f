// SPDX-License-Identifier: GPL-3.0-or-later
// Preconditioners z = M⁻¹ r for the Krylov solvers on a 7-point stencil.
//
//   Jacobi:        z_P = r_P / a_P
//   Gauss–Seidel:  one symmetric red-black sweep (red, black, red;
//                  smoother.h) on A z = r from z = 0 — a fixed linear
//                  operator, symmetric when A is symmetric.
//
// Each holds a pointer to the stencil passed to setup(); the stencil must
// outlive the preconditioner's use.
#pragma once

#include <vector>

#include "linalg/stencil.h"

namespace gridfree {

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // z = M⁻¹ r (z is resized).
  virtual void apply(const std::vector<double>& r, std::vector<double>& z) = 0;
};

class JacobiPreconditioner final : public Preconditioner {
 public:
  void setup(const Stencil7& s);
  void apply(const std::vector<double>& r, std::vector<double>& z) override;

 private:
  std::vector<double> inverse_diagonal_;
};

class GaussSeidelPreconditioner final : public Preconditioner {
 public:
  void setup(const Stencil7& s) { stencil_ = &s; }
  void apply(const std::vector<double>& r, std::vector<double>& z) override;

 private:
  const Stencil7* stencil_ = nullptr;
  std::vector<double> scratch_;
};

}  // namespace gridfree

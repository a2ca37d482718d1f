// SPDX-License-Identifier: GPL-3.0-or-later
// The printed digits of values and uncertainties (extrap/value_format.h):
// two significant digits of U, the value to the same decimal, and the edge
// cases a report meets (U = 0, U ≫ |f|, negatives, non-finite, tiny and
// huge magnitudes).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "extrap/value_format.h"

namespace gridfree {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ValueFormat, TwoSignificantDigitsOfUAndTheValueToTheSameDecimal) {
  EXPECT_EQ(format_value_u(1015.855, 1.4637), "1015.9 ± 1.5");
  EXPECT_EQ(format_value_u(1017.04, 1.5), "1017.0 ± 1.5");  // the trailing zero stays
  EXPECT_EQ(format_value_u(1021.0002, 0.0013), "1021.0002 ± 0.0013");
  EXPECT_EQ(format_value_u(1021.0, 0.0013), "1021.0000 ± 0.0013");
  EXPECT_EQ(format_value_u(52134.0, 270.0), "52130 ± 270");
  EXPECT_EQ(format_value_u(52134.0, 27.0), "52134 ± 27");
  EXPECT_EQ(format_value_u(0.123456, 0.00042), "0.12346 ± 0.00042");
}

TEST(ValueFormat, RoundingUpOfUMovesTheDecimal) {
  // 0.0996 has two significant digits 0.10: the value to 2 decimals, not 3.
  EXPECT_EQ(uncertainty_exponent(0.0996), -2);
  EXPECT_EQ(format_value_u(3.14159, 0.0996), "3.14 ± 0.10");
  EXPECT_EQ(format_value_u(3.14159, 9.96), "3 ± 10");
  EXPECT_EQ(uncertainty_exponent(1.37), -1);
  EXPECT_EQ(uncertainty_exponent(37.0), 0);
  EXPECT_EQ(uncertainty_exponent(370.0), 1);
}

TEST(ValueFormat, NegativeValuesAndNoMinusZero) {
  EXPECT_EQ(format_value_u(-1015.855, 1.4637), "-1015.9 ± 1.5");
  EXPECT_EQ(format_value_u(-0.004, 1.3), "0.0 ± 1.3");
  EXPECT_EQ(format_value_for_u(-0.004, 1.3), "0.0");
}

TEST(ValueFormat, UMuchLargerThanTheValue) {
  EXPECT_EQ(format_value_u(0.003, 25.0), "0 ± 25");
  EXPECT_EQ(format_value_u(-7.0, 2500.0), "0 ± 2500");
}

TEST(ValueFormat, ZeroUIsSaidNotPaddedWithZeros) {
  EXPECT_EQ(format_value_u(1003.0, 0.0), "1003 ± 0");
  EXPECT_EQ(format_value_u(1003.123456789, 0.0), "1003.12 ± 0");
  EXPECT_EQ(format_value_u(1003.0, 0.0).find("0.000"), std::string::npos);
}

TEST(ValueFormat, WithoutAUsableUTheValueAlone) {
  EXPECT_EQ(format_value_u(1015.855, std::nullopt), "1015.86");
  EXPECT_EQ(format_value_u(1015.855, kNaN), "1015.86");
  EXPECT_EQ(format_value_u(1015.855, -1.0), "1015.86");
  EXPECT_EQ(format_value_u(1015.855, kInf, 4), "1016");
  EXPECT_FALSE(uncertainty_exponent(std::nullopt));
  EXPECT_FALSE(uncertainty_exponent(0.0));
}

TEST(ValueFormat, NonFiniteValuesArePrintedAsSuch) {
  EXPECT_EQ(format_value_u(kNaN, 1.0), "nan");
  EXPECT_EQ(format_value_u(kInf, 1.0), "inf");
  EXPECT_EQ(format_value_u(-kInf, 1.0), "-inf");
  EXPECT_EQ(format_value_for_u(kNaN, 1.0), "nan");
  EXPECT_EQ(format_cell_size(kNaN), "nan");
  EXPECT_EQ(format_percent_fixed(kInf), "inf%");
}

TEST(ValueFormat, TinyAndHugeMagnitudesShareOnePowerOfTen) {
  EXPECT_EQ(format_value_u(1.23456e-12, 3.1e-15), "(1.2346 ± 0.0031)e-12");
  EXPECT_EQ(format_value_u(6.02214e23, 3.7e19), "(6.02214 ± 0.00037)e+23");
  // U larger than the value: U's power of ten.
  EXPECT_EQ(format_value_u(2e-9, 3.4e-8), "(0.2 ± 3.4)e-8");
  // Small but ordinary: fixed notation down to U = 1e-6.
  EXPECT_EQ(format_value_u(0.0012345, 0.0000021), "0.0012345 ± 0.0000021");
  EXPECT_EQ(format_value_for_u(1.23456e-12, 3.1e-15), "1.2346e-12");
}

TEST(ValueFormat, VerdictArithmeticAgreesWithTheQuotedDigits) {
  // f0 = 1017.04 ± 1.5 beyond the largest value 1015.855: the difference of
  // the values as printed (1017.0 − 1015.9), not 1.185 rounded to 1.2.
  const double u = 1.5;
  const double d = rounded_for_u(1017.04, u) - rounded_for_u(1015.855, u);
  EXPECT_EQ(format_value_for_u(d, u), "1.1");
  EXPECT_EQ(format_value_for_u(1015.855, u), "1015.9");
  EXPECT_EQ(rounded_for_u(1015.855, std::nullopt), 1015.855);
}

TEST(ValueFormat, DigitsOfF0ComeFromU0ElseU1) {
  EXPECT_EQ(*f0_digits_u(0.2, 1.5), 0.2);
  EXPECT_EQ(*f0_digits_u(0.0, 1.5), 1.5);
  EXPECT_EQ(*f0_digits_u(std::nullopt, 1.5), 1.5);
  EXPECT_FALSE(f0_digits_u(std::nullopt, std::nullopt));
}

TEST(ValueFormat, VerdictLineOfTheConsole) {
  EXPECT_EQ(verdict_line("converged", 1017.04, 1.5, 1015.855, 1.4637, 0.00149),
            "verdict converged: f0 = 1017.0 ± 1.5, finest f1 = 1015.9 ± 1.5 (RDE 0.149%)");
  // Without U₀: f0 to the digits of U₁, no "±" after it.
  EXPECT_EQ(verdict_line("pre-asymptotic", 1017.04, std::nullopt, 1015.855, 0.37, std::nullopt),
            "verdict pre-asymptotic: f0 = 1017.04, finest f1 = 1015.86 ± 0.37");
  EXPECT_EQ(verdict_line("insufficient_grids", std::nullopt, std::nullopt, std::nullopt, std::nullopt, std::nullopt),
            "verdict insufficient_grids");
}

TEST(ValueFormat, CellSizeHasOnePrecision) {
  EXPECT_EQ(format_cell_size(1.295), "1.295");
  EXPECT_EQ(format_cell_size(0.78612), "0.7861");
  EXPECT_EQ(format_cell_size(1.3), "1.3");
  EXPECT_EQ(format_cell_size(12.5), "12.5");
}

TEST(ValueFormat, PercentagesNeverSwitchNotation) {
  EXPECT_EQ(format_percent_fixed(9.38e-8), "0.00000938%");
  EXPECT_EQ(format_percent_fixed(1.09e-6), "0.000109%");
  EXPECT_EQ(format_percent_fixed(0.0518e-2), "0.0518%");
  EXPECT_EQ(format_percent_fixed(0.0938), "9.38%");
  EXPECT_EQ(format_percent_fixed(-0.0938), "-9.38%");
  EXPECT_EQ(format_percent_fixed(1.5), "150%");
  EXPECT_EQ(format_percent_fixed(123.45), "12345%");
  EXPECT_EQ(format_percent_fixed(0.9996), "100%");  // 3 digits of 99.96
  EXPECT_EQ(format_percent_fixed(0.0), "0%");
}

}  // namespace
}  // namespace gridfree

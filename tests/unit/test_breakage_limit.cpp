// Breakage limit, eq. 2-7 and 10 of Ciantia et al. (2014), against hand calculations.
#include <gtest/gtest.h>

#include <cmath>

#include "crush_breakage_limit.h"
#include "crush_constants.h"
#include "crush_model_error.h"

using namespace crush;

namespace {
const Material quartz{7.8e9, 0.3};  // E = 2G(1+nu) with the paper's G = 3 GPa, nu = 0.3
const Material steel{210e9, 0.29};
}  // namespace

namespace {
// eq. 5 written out as the paper gives it: F_lim = [sigma_lim pi (3 r'/(4 E'))^(2/3)]^3.
double eq5_limit_force(double sigma_lim, double r_eff, double E_eff)
{
  return std::pow(sigma_lim * pi * std::pow(3.0 * r_eff / (4.0 * E_eff), 2.0 / 3.0), 3.0);
}
// The ratio as the breakage check computes it: contact term x strength term.
double checked_ratio(double F, double r_eff, double E_eff, double sigma_lim)
{
  return force_ratio(contact_load(F, r_eff, limit_factor(E_eff)), strength_term(sigma_lim));
}
}  // namespace

TEST(BreakageLimit, ProductIsEq7BallBallByHand)
{
  // Two quartz spheres, r1 = 0.1 mm and r2 = 0.2 mm, sigma_lim = 5 GPa: r' = 2e-4/3 m (eq. 3).
  const double r_eff = 1.0 / (1.0 / 1e-4 + 1.0 / 2e-4);
  const double E_eff = effective_modulus(quartz, quartz);
  EXPECT_NEAR(E_eff, 7.8e9 / (2.0 * 0.91), 1e-6);  // equal materials: E/(2(1-nu^2))
  // Magnitude by hand: E' = 4.2857e9 Pa, 3r'/(4E') = 1.16667e-14, ^2 = 1.36111e-28,
  // (5e9 pi)^3 = 3.8758e30: F_lim = 527.5 N.
  const double f_lim = eq5_limit_force(5e9, r_eff, E_eff);
  EXPECT_NEAR(f_lim, 527.5, 0.1);
  for (double F : {1.0, 0.5 * f_lim, f_lim, 3.0 * f_lim})
    EXPECT_NEAR(checked_ratio(F, r_eff, E_eff, 5e9), F / f_lim, 1e-13 * F / f_lim);
  EXPECT_NEAR(checked_ratio(f_lim, r_eff, E_eff, 5e9), 1.0, 1e-13);
}

TEST(BreakageLimit, ProductIsEq7BallPlaneWithWallMaterialAndParticleRadius)
{
  const double r = 1.5e-4;  // a plane: r' = r
  const double E_eff = effective_modulus(quartz, steel);
  const double by_hand = 1.0 / ((1 - 0.09) / 7.8e9 + (1 - 0.29 * 0.29) / 210e9);
  EXPECT_NEAR(E_eff, by_hand, 1e-9 * by_hand);
  const double f_lim = eq5_limit_force(3.3e9, r, E_eff);
  EXPECT_NEAR(checked_ratio(0.7 * f_lim, r, E_eff, 3.3e9), 0.7, 1e-13);
  // At F_lim the mean Hertz contact pressure F/(pi r_H^2), r_H of eq. 2, equals sigma_lim (eq. 1).
  const double r_h = std::cbrt(3.0 * f_lim * r / (4.0 * E_eff));
  EXPECT_NEAR(f_lim / (pi * r_h * r_h), 3.3e9, 1e-9 * 3.3e9);
}

TEST(BreakageLimit, SizeEffectAndUpscalingEnterAsEq10)
{
  const double s = 5e9, d0 = 2e-3, m = 10.0;
  // d = d0, N = 1: no correction.
  EXPECT_DOUBLE_EQ(size_scaled_strength(s, d0, d0, m, 1.0), s);
  // Halving d raises the strength by 2^(3/m).
  EXPECT_NEAR(size_scaled_strength(s, d0 / 2, d0, m, 1.0), s * std::pow(2.0, 0.3), 1e-6);
  // Doubling d and N together changes nothing (eq. 10).
  const double d = 2.1e-4;
  EXPECT_NEAR(size_scaled_strength(s, 2 * d, d0, m, 2.0), size_scaled_strength(s, d, d0, m, 1.0),
              1e-12 * s);
  // N = 1.5 on a grain scaled by 1.5: the same strength as the unscaled grain.
  EXPECT_NEAR(size_scaled_strength(s, 1.5 * d, d0, m, 1.5), size_scaled_strength(s, d, d0, m, 1.0),
              1e-12 * s * 3);
}

TEST(BreakageLimit, ZeroStrengthBreaksUnderAnyLoadOnly)
{
  const double E_eff = effective_modulus(quartz, quartz);
  EXPECT_TRUE(std::isinf(checked_ratio(1e-12, 1e-4, E_eff, 0.0)));
  EXPECT_EQ(checked_ratio(0.0, 1e-4, E_eff, 0.0), 0.0);  // no load: stays whole
}

TEST(BreakageLimit, InvalidInputNamesTheParameter)
{
  try {
    effective_modulus({-1.0, 0.3}, quartz);
    FAIL() << "no exception";
  } catch (const ModelError &e) {
    EXPECT_NE(std::string(e.what()).find("youngs_modulus"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("in (0, 3e13] Pa"), std::string::npos);
  }
  EXPECT_THROW(effective_modulus({1e300, 0.3}, quartz), ModelError);  // beyond any solid: overflows
  EXPECT_NO_THROW(effective_modulus({3e13, 0.3}, quartz));
  EXPECT_THROW(effective_modulus({1e9, 0.5}, quartz), ModelError);
  EXPECT_THROW(size_scaled_strength(5e9, 1e-4, 2e-3, 0.0, 1.0), ModelError);
  EXPECT_THROW(size_scaled_strength(5e9, 1e-4, 2e-3, 10.0, 0.0), ModelError);
  EXPECT_THROW(size_scaled_strength(5e9, 1e-4, -2e-3, 10.0, 1.0), ModelError);
  EXPECT_THROW(size_scaled_strength(-1.0, 1e-4, 2e-3, 10.0, 1.0), ModelError);
}

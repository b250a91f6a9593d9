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

TEST(BreakageLimit, BallBallByHand)
{
  // Two quartz spheres, r1 = 0.1 mm and r2 = 0.2 mm, sigma_lim = 5 GPa.
  const double r1 = 1e-4, r2 = 2e-4;
  const double r_eff = effective_radius(r1, r2);
  EXPECT_DOUBLE_EQ(r_eff, 2e-4 / 3.0);  // 1/(1/1e-4 + 1/2e-4)
  const double E_eff = effective_modulus(quartz, quartz);
  EXPECT_NEAR(E_eff, 7.8e9 / (2.0 * 0.91), 1e-6);  // equal materials: E/(2(1-nu^2))
  // F_lim = [5e9 pi (3 (2e-4/3) / (4 E'))^(2/3)]^3, written out step by step.
  const double area_factor = std::pow(3.0 * r_eff / (4.0 * E_eff), 2.0 / 3.0);
  const double expected = std::pow(5e9 * pi * area_factor, 3.0);
  EXPECT_NEAR(limit_force(5e9, r_eff, E_eff), expected, 1e-12 * expected);
  // Magnitude check done by hand: E' = 4.2857e9 Pa, 3r'/(4E') = 1.16667e-14, ^2 = 1.36111e-28,
  // (5e9 pi)^3 = 3.8758e30: F_lim = 527.5 N.
  EXPECT_NEAR(limit_force(5e9, r_eff, E_eff), 527.5, 0.1);
}

TEST(BreakageLimit, BallPlaneUsesWallMaterialAndParticleRadius)
{
  const double r = 1.5e-4;
  EXPECT_DOUBLE_EQ(effective_radius_plane(r), r);
  const double E_eff = effective_modulus(quartz, steel);
  const double by_hand = 1.0 / ((1 - 0.09) / 7.8e9 + (1 - 0.29 * 0.29) / 210e9);
  EXPECT_NEAR(E_eff, by_hand, 1e-9 * by_hand);
  const double f_lim = limit_force(5e9, r, E_eff);
  const double expected = std::pow(5e9 * pi, 3.0) * std::pow(3.0 * r / (4.0 * E_eff), 2.0);
  EXPECT_NEAR(f_lim, expected, 1e-12 * expected);
  // A plane is stiffer contact than an equal ball: same sigma_lim gives a larger F_lim than r' = r/2.
  EXPECT_GT(f_lim, limit_force(5e9, effective_radius(r, r), E_eff));
}

TEST(BreakageLimit, RatioIsOneExactlyAtTheLimitAndHertzAreaMatches)
{
  const double r_eff = 7e-5, E_eff = effective_modulus(quartz, quartz), sigma = 3.3e9;
  const BreakageLimit limit(sigma, E_eff);
  const double f_lim = limit.limit_force(r_eff);
  EXPECT_NEAR(limit.force_ratio(f_lim, r_eff), 1.0, 1e-14);
  EXPECT_NEAR(limit.force_ratio(0.5 * f_lim, r_eff), 0.5, 1e-14);
  // At F_lim the mean Hertz contact pressure F/(pi r_H^2) equals sigma_lim (eq. 1 with eq. 2).
  const double r_h = hertz_contact_radius(f_lim, r_eff, E_eff);
  EXPECT_NEAR(f_lim / (pi * r_h * r_h), sigma, 1e-9 * sigma);
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

TEST(BreakageLimit, ZeroStrengthBreaksUnderAnyLoad)
{
  const BreakageLimit limit(0.0, 1e9);
  EXPECT_TRUE(std::isinf(limit.force_ratio(1e-12, 1e-4)));
  EXPECT_EQ(limit.force_ratio(0.0, 1e-4), 0.0);
}

TEST(BreakageLimit, InvalidInputNamesTheParameter)
{
  try {
    effective_radius(-1.0, 1.0);
    FAIL() << "no exception";
  } catch (const ModelError &e) {
    EXPECT_NE(std::string(e.what()).find("radius r1"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("> 0 m"), std::string::npos);
  }
  EXPECT_THROW(effective_modulus({-1.0, 0.3}, quartz), ModelError);
  EXPECT_THROW(effective_modulus({1e9, 0.5}, quartz), ModelError);
  EXPECT_THROW(size_scaled_strength(5e9, 1e-4, 2e-3, 0.0, 1.0), ModelError);
  EXPECT_THROW(size_scaled_strength(5e9, 1e-4, 2e-3, 10.0, 0.0), ModelError);
  EXPECT_THROW(size_scaled_strength(5e9, 1e-4, -2e-3, 10.0, 1.0), ModelError);
  EXPECT_THROW(size_scaled_strength(-1.0, 1e-4, 2e-3, 10.0, 1.0), ModelError);
  EXPECT_THROW(hertz_contact_radius(-1.0, 1e-4, 1e9), ModelError);
  EXPECT_THROW(BreakageLimit(-1.0, 1e9), ModelError);
  EXPECT_THROW(BreakageLimit(1e9, 0.0), ModelError);
  EXPECT_THROW(limit_force(1e9, 0.0, 1e9), ModelError);
}

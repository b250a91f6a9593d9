// The bound of fix crush's adaptive check (crush_check_bound.h) against a Hertzian contact evaluated
// as the contact model and the breakage check evaluate it.
#include <gtest/gtest.h>

#include <cmath>

#include "crush_breakage_limit.h"
#include "crush_check_bound.h"
#include "hertz_mindlin_contact_load.h"
#include "hertz_mindlin_scaled_law.h"

using namespace crush;

namespace {
const Material quartz{7.8e9, 0.3};
const ShearMaterial quartz_shear = shear_material(7.8e9, 0.3);

// F_n / F_lim of particle i (radius ri, strength sigma) in contact with j (radius rj) at overlap U:
// eq. 8's elastic force, then eq. 5 through the contact and strength terms.
double ratio_at(double U, double ri, double rj, double sigma)
{
  const HertzMindlinCoefficients c = hertz_mindlin_coefficients(quartz_shear, quartz_shear);
  const double Dt = diameter_term_from_radii(ri, rj);
  const double Fn = contact_stiffness(c, Dt, U).normal * U;
  const double lf = limit_factor(effective_modulus(quartz, quartz));
  return force_ratio(contact_load(Fn, 0.5 * Dt, lf), strength_term(sigma));
}

double coefficient()
{
  return ratio_coefficient(hertz_mindlin_coefficients(quartz_shear, quartz_shear).normal,
                           limit_factor(effective_modulus(quartz, quartz)));
}
}  // namespace

// g = ratio^(2/3) is linear in U/r': the ratio coefficient reproduces the check's ratio.
TEST(CheckBound, RatioIsCoefficientTimesOverlapPower)
{
  const double ri = 2e-4, rj = 1e-4, sigma = 2e9, U = 3e-7, r_eff = ri * rj / (ri + rj);
  EXPECT_NEAR(ratio_at(U, ri, rj, sigma), coefficient() * strength_term(sigma) * std::pow(U / r_eff, 1.5),
              1e-12 * ratio_at(U, ri, rj, sigma));
}

// The worst case of the bound: the partner is the smallest particle present and both bodies approach
// by the allowance D each. The contact then reaches the limit (less the margin), and not before.
TEST(CheckBound, AllowanceIsTightForTheSmallestPartner)
{
  const double ri = 2e-4, rs = 5e-5, sigma = 3e8, U0 = 4e-7;
  const double r0 = ratio_at(U0, ri, rs, sigma);
  ASSERT_GT(r0, 0.05);
  ASSERT_LT(r0, 0.9);
  const double growth = ratio_growth(coefficient(), strength_term(sigma), ri, rs);
  const double D = allowed_displacement(r0, growth);
  EXPECT_NEAR(ratio_at(U0 + 2.0 * D, ri, rs, sigma), 1.0, 1e-5);
  EXPECT_LT(ratio_at(U0 + 2.0 * D, ri, rs, sigma), 1.0);
  EXPECT_GT(ratio_at(U0 + 2.0 * D * 1.001, ri, rs, sigma), 1.0);
  // A larger partner: the same approach leaves the contact further from the limit.
  EXPECT_LT(ratio_at(U0 + 2.0 * D, ri, 4.0 * rs, sigma), ratio_at(U0 + 2.0 * D, ri, rs, sigma));
}

// A contact that did not exist at the check (U <= 0) is covered: from U = 0, 2D is the whole overlap.
TEST(CheckBound, NewContactStartsFromZero)
{
  const double ri = 1e-4, rs = 1e-4, sigma = 1e9;
  const double growth = ratio_growth(coefficient(), strength_term(sigma), ri, rs);
  const double D = allowed_displacement(0.0, growth);
  EXPECT_NEAR(ratio_at(2.0 * D, ri, rs, sigma), 1.0, 1e-5);
}

// At or above the limit, or with zero strength, nothing may move unchecked.
TEST(CheckBound, NoAllowanceAtTheLimitOrForZeroStrength)
{
  EXPECT_EQ(allowed_displacement(1.0, 1e3), 0.0);
  EXPECT_EQ(allowed_displacement(2.0, 1e3), 0.0);
  EXPECT_EQ(allowed_displacement(0.0, ratio_growth(coefficient(), strength_term(0.0), 1e-4, 1e-4)), 0.0);
  EXPECT_TRUE(std::isinf(allowed_displacement(0.5, 0.0)));  // never breaks (dmin, group)
}

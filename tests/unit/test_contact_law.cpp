// Scaled Hertz-Mindlin law, eq. 8-9: by hand for unequal spheres and materials, and against the
// stiffness forms LIGGGHTS' hertz / tangential history use for equal materials.
#include <gtest/gtest.h>

#include <cmath>

#include "crush_constants.h"
#include "crush_model_error.h"
#include "hertz_mindlin_scaled_law.h"

using namespace crush;

TEST(ContactLaw, UnequalSpheresAndMaterialsByHand)
{
  const ShearMaterial a{3e9, 0.3}, b{5e9, 0.2};
  const double d1 = 0.2e-3, d2 = 0.4e-3, U = 1e-6;
  const HertzMindlinScaled law(a, b, d1, d2);
  // <G> = 4e9, <nu> = 0.25, D1D2/(D1+D2) = 0.08e-6/0.6e-3 = 1.3333e-4 m.
  const double Dt = 0.2e-3 * 0.4e-3 / 0.6e-3;
  EXPECT_NEAR(law.diameter_term(), Dt, 1e-18);
  const double kn = 2.0 * 4e9 * std::sqrt(2.0 * Dt) / (3.0 * 0.75) * std::sqrt(U);
  EXPECT_NEAR(law.normal_stiffness(U), kn, 1e-12 * kn);
  // Numbers: sqrt(2.6667e-4) = 0.016330, k_N = 8e9 * 0.0163299 / 2.25 * 1e-3 = 5.8062e4 N/m.
  EXPECT_NEAR(law.normal_stiffness(U), 5.8062e4, 1.0);
  const double F = law.normal_force(U);
  EXPECT_NEAR(F, kn * U, 1e-12 * kn * U);
  const double ks = 2.0 * std::cbrt(16e18 * 3.0 * 0.75 * Dt) / 1.75 * std::cbrt(F);
  EXPECT_NEAR(law.shear_stiffness(F), ks, 1e-12 * ks);
  EXPECT_EQ(law.shear_stiffness(F), law.shear_stiffness(-F));  // |F|
  EXPECT_EQ(law.normal_stiffness(-1e-9), 0.0);  // no contact, no stiffness
}

TEST(ContactLaw, EqualMaterialsGiveLiggghtsHertzAndMindlinForms)
{
  const ShearMaterial m{3e9, 0.3};
  const double E = youngs_modulus(m);
  EXPECT_DOUBLE_EQ(E, 7.8e9);
  for (double r2 : {0.1e-3, 0.3e-3}) {
    const double r1 = 0.15e-3, U = 2e-7;
    const HertzMindlinScaled law(m, m, 2 * r1, 2 * r2);
    const double R_star = r1 * r2 / (r1 + r2);
    // LIGGGHTS normal_model_hertz: Y* = 1/((1-nu^2)/E + (1-nu^2)/E), k_n = 4/3 Y* sqrt(R* U).
    const double Y_star = E / (2.0 * (1.0 - 0.09));
    const double kn_liggghts = 4.0 / 3.0 * Y_star * std::sqrt(R_star * U);
    EXPECT_NEAR(law.normal_stiffness(U), kn_liggghts, 1e-12 * kn_liggghts);
    // tangential history: G* = 1/((2-nu)/G + (2-nu)/G), k_t = 8 G* sqrt(R* U).
    const double G_star = 3e9 / (2.0 * (2.0 - 0.3));
    const double kt_liggghts = 8.0 * G_star * std::sqrt(R_star * U);
    EXPECT_NEAR(law.shear_stiffness(law.normal_force(U)), kt_liggghts, 1e-12 * kt_liggghts);
  }
}

TEST(ContactLaw, PerTypePairCoefficientsEqualThePapersForm)
{
  const ShearMaterial a{3e9, 0.3}, b{5e9, 0.2};
  const HertzMindlinCoefficients c = hertz_mindlin_coefficients(a, b);
  for (double U : {1e-9, 1e-7, 3e-6}) {
    const double r1 = 0.1e-3, r2 = 0.35e-3;
    const HertzMindlinScaled law(a, b, 2 * r1, 2 * r2);
    const double Dt = diameter_term_from_radii(r1, r2);
    EXPECT_NEAR(Dt, law.diameter_term(), 1e-18);
    const double kn = law.normal_stiffness(U);
    EXPECT_NEAR(normal_stiffness(c, Dt, U), kn, 1e-12 * kn);
    const double ks = law.shear_stiffness(law.normal_force(U));  // eq. 9 with |F| = k_N U
    EXPECT_NEAR(shear_stiffness(c, Dt, U), ks, 1e-12 * ks);
  }
  EXPECT_THROW(hertz_mindlin_coefficients({3e9, 0.5}, b), ModelError);
}

TEST(ContactLaw, PlaneIsASphereOfInfiniteDiameterOfTheWallMaterial)
{
  const ShearMaterial ball{3e9, 0.3}, wall{80e9, 0.25};
  const double d = 0.3e-3, U = 1e-7;
  const HertzMindlinScaled plane = HertzMindlinScaled::ball_plane(ball, wall, d);
  EXPECT_DOUBLE_EQ(plane.diameter_term(), d);
  // The limit of ever larger partner spheres.
  const HertzMindlinScaled huge(ball, wall, d, 1e6 * d);
  EXPECT_NEAR(plane.normal_stiffness(U) / huge.normal_stiffness(U), 1.0, 1e-6);
  const double kn = 2.0 * 41.5e9 * std::sqrt(2.0 * d) / (3.0 * (1.0 - 0.275)) * std::sqrt(U);
  EXPECT_NEAR(plane.normal_stiffness(U), kn, 1e-12 * kn);
}

TEST(ContactLaw, RayleighTimeStep)
{
  // Quartz-like grain, r = 0.05 mm, rho = 2650, G = 3 GPa, nu = 0.3:
  // pi 5e-5 sqrt(2650/3e9) / (0.1631*0.3 + 0.8766) = 1.5708e-4 * 9.3986e-4 / 0.92553 = 1.5951e-7 s.
  const double t = rayleigh_time_step(0.05e-3, 2650.0, {3e9, 0.3});
  EXPECT_NEAR(t, pi * 0.05e-3 * std::sqrt(2650.0 / 3e9) / (0.1631 * 0.3 + 0.8766), 1e-20);
  EXPECT_NEAR(t, 1.5951e-7, 1e-10);
  // Linear in radius.
  EXPECT_NEAR(rayleigh_time_step(0.1e-3, 2650.0, {3e9, 0.3}), 2.0 * t, 1e-18);
}

TEST(ContactLaw, InvalidInput)
{
  EXPECT_THROW(HertzMindlinScaled({0.0, 0.3}, {3e9, 0.3}, 1e-4, 1e-4), ModelError);
  EXPECT_THROW(HertzMindlinScaled({3e9, 0.6}, {3e9, 0.3}, 1e-4, 1e-4), ModelError);
  EXPECT_THROW(HertzMindlinScaled({3e9, 0.3}, {3e9, 0.3}, 0.0, 1e-4), ModelError);
  EXPECT_THROW(HertzMindlinScaled::ball_plane({3e9, 0.3}, {3e9, 0.3}, -1e-4), ModelError);
  EXPECT_THROW(rayleigh_time_step(0.0, 2650.0, {3e9, 0.3}), ModelError);
  EXPECT_THROW(rayleigh_time_step(1e-4, 0.0, {3e9, 0.3}), ModelError);
}

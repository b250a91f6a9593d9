// Scaled Hertz-Mindlin law, eq. 8-9: by hand for unequal spheres and materials, and against the
// stiffness forms LIGGGHTS' hertz / tangential history use for equal materials.
#include <gtest/gtest.h>

#include <cmath>

#include "crush_constants.h"
#include "crush_model_error.h"
#include "hertz_mindlin_scaled_law.h"

using namespace crush;

namespace {
// eq. 8 and eq. 9 written out as the paper gives them, for mean properties G, nu and Dt = D1D2/(D1+D2).
double eq8_normal_stiffness(double G, double nu, double Dt, double U)
{
  return 2.0 * G * std::sqrt(2.0 * Dt) / (3.0 * (1.0 - nu)) * std::sqrt(U);
}
double eq9_shear_stiffness(double G, double nu, double Dt, double F)
{
  return 2.0 * std::cbrt(G * G * 3.0 * (1.0 - nu) * Dt) / (2.0 - nu) * std::cbrt(std::fabs(F));
}
}  // namespace

TEST(ContactLaw, UnequalSpheresAndMaterialsByHand)
{
  const ShearMaterial a{3e9, 0.3}, b{5e9, 0.2};
  const double r1 = 0.1e-3, r2 = 0.2e-3, U = 1e-6;
  // <G> = 4e9, <nu> = 0.25, D1D2/(D1+D2) = 0.08e-6/0.6e-3 = 1.3333e-4 m.
  const double Dt = diameter_term_from_radii(r1, r2);
  EXPECT_NEAR(Dt, 0.2e-3 * 0.4e-3 / 0.6e-3, 1e-18);
  const HertzMindlinStiffness k = contact_stiffness(hertz_mindlin_coefficients(a, b), Dt, U);
  const double kn = eq8_normal_stiffness(4e9, 0.25, Dt, U);
  EXPECT_NEAR(k.normal, kn, 1e-12 * kn);
  // Numbers: sqrt(2.6667e-4) = 0.016330, k_N = 8e9 * 0.0163299 / 2.25 * 1e-3 = 5.8062e4 N/m.
  EXPECT_NEAR(k.normal, 5.8062e4, 1.0);
  // eq. 9 with the elastic normal force |F_n| = k_N U.
  const double ks = eq9_shear_stiffness(4e9, 0.25, Dt, kn * U);
  EXPECT_NEAR(k.shear, ks, 1e-12 * ks);
  EXPECT_DOUBLE_EQ(tangent_normal_stiffness(k.normal), 1.5 * k.normal);
  // The tangent is dF/dU of F = k_N(U) U, by central differences.
  const double h = 1e-4 * U;
  const double dF = (contact_stiffness(hertz_mindlin_coefficients(a, b), Dt, U + h).normal * (U + h) -
                     contact_stiffness(hertz_mindlin_coefficients(a, b), Dt, U - h).normal * (U - h)) / (2 * h);
  EXPECT_NEAR(tangent_normal_stiffness(k.normal), dF, 1e-6 * dF);
}

TEST(ContactLaw, EqualMaterialsGiveLiggghtsHertzAndMindlinForms)
{
  const ShearMaterial m = shear_material(7.8e9, 0.3);
  EXPECT_DOUBLE_EQ(m.shear_modulus, 3e9);
  EXPECT_DOUBLE_EQ(m.poisson_ratio, 0.3);
  const HertzMindlinCoefficients c = hertz_mindlin_coefficients(m, m);
  for (double r2 : {0.1e-3, 0.3e-3}) {
    const double r1 = 0.15e-3, U = 2e-7;
    const HertzMindlinStiffness k = contact_stiffness(c, diameter_term_from_radii(r1, r2), U);
    const double R_star = r1 * r2 / (r1 + r2);
    // LIGGGHTS normal_model_hertz: Y* = 1/((1-nu^2)/E + (1-nu^2)/E), k_n = 4/3 Y* sqrt(R* U).
    const double Y_star = 7.8e9 / (2.0 * (1.0 - 0.09));
    const double kn_liggghts = 4.0 / 3.0 * Y_star * std::sqrt(R_star * U);
    EXPECT_NEAR(k.normal, kn_liggghts, 1e-12 * kn_liggghts);
    // tangential history: G* = 1/((2-nu)/G + (2-nu)/G), k_t = 8 G* sqrt(R* U).
    const double G_star = 3e9 / (2.0 * (2.0 - 0.3));
    const double kt_liggghts = 8.0 * G_star * std::sqrt(R_star * U);
    EXPECT_NEAR(k.shear, kt_liggghts, 1e-12 * kt_liggghts);
  }
}

TEST(ContactLaw, PerTypePairCoefficientsEqualThePapersForm)
{
  const ShearMaterial a{3e9, 0.3}, b{5e9, 0.2};
  const HertzMindlinCoefficients c = hertz_mindlin_coefficients(a, b);
  for (double U : {1e-9, 1e-7, 3e-6}) {
    const double Dt = diameter_term_from_radii(0.1e-3, 0.35e-3);
    const HertzMindlinStiffness k = contact_stiffness(c, Dt, U);
    const double kn = eq8_normal_stiffness(4e9, 0.25, Dt, U);
    EXPECT_NEAR(k.normal, kn, 1e-12 * kn);
    const double ks = eq9_shear_stiffness(4e9, 0.25, Dt, kn * U);
    EXPECT_NEAR(k.shear, ks, 1e-12 * ks);
  }
  EXPECT_THROW(hertz_mindlin_coefficients({3e9, 0.5}, b), ModelError);
}

TEST(ContactLaw, PlaneIsASphereOfInfiniteDiameterOfTheWallMaterial)
{
  const ShearMaterial ball{3e9, 0.3}, wall{80e9, 0.25};
  const HertzMindlinCoefficients c = hertz_mindlin_coefficients(ball, wall);
  const double d = 0.3e-3, U = 1e-7;
  // The plane's Dt = D1 is the limit of ever larger partner spheres.
  const double plane = contact_stiffness(c, d, U).normal;
  const double huge = contact_stiffness(c, diameter_term_from_radii(0.5 * d, 0.5e6 * d), U).normal;
  EXPECT_NEAR(plane / huge, 1.0, 1e-6);
  const double kn = eq8_normal_stiffness(41.5e9, 0.275, d, U);
  EXPECT_NEAR(plane, kn, 1e-12 * kn);
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
  EXPECT_THROW(hertz_mindlin_coefficients({0.0, 0.3}, {3e9, 0.3}), ModelError);
  EXPECT_THROW(hertz_mindlin_coefficients({3e9, 0.6}, {3e9, 0.3}), ModelError);
  EXPECT_THROW(rayleigh_time_step(0.0, 2650.0, {3e9, 0.3}), ModelError);
  EXPECT_THROW(rayleigh_time_step(1e-4, 0.0, {3e9, 0.3}), ModelError);
}

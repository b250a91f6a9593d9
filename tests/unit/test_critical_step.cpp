// PFC's automatic time step for Hertz-Mindlin contacts.
#include <gtest/gtest.h>

#include <cmath>

#include "critical_step_law.h"

namespace {
const crush::ShearMaterial kQuartz{3e9, 0.3};  // Table 1

// A ball of diameter d between two fixed walls, both contacts at overlap U (eq. 8, wall: Dt = d).
double wall_contact_force(const crush::HertzMindlinCoefficients &c, double d, double U)
{
  return U > 0.0 ? crush::contact_stiffness(c, d, U).normal * U : 0.0;
}

// Velocity Verlet (LIGGGHTS' nve/sphere) of that ball, displaced by 'offset' from the middle where
// both walls overlap it by U0; returns the largest displacement reached (m) in 'steps' steps, with the
// step either fixed (dt_factor x critical of the initial state) or recomputed every step.
double largest_excursion(double dt_factor, bool adaptive, int steps)
{
  const auto c = crush::hertz_mindlin_coefficients(kQuartz, kQuartz);
  const double d = 0.4e-3, U0 = 1e-7, mass = 2650.0 * M_PI / 6.0 * d * d * d;
  double x = 0.2 * U0, v = 0.0, largest = 0.0;
  auto force = [&](double pos) { return wall_contact_force(c, d, U0 - pos) - wall_contact_force(c, d, U0 + pos); };
  auto step_at = [&](double pos) {
    crush::ContactStiffness sum;
    if (U0 - pos > 0.0) crush::add_contact(sum, c, d, U0 - pos);
    if (U0 + pos > 0.0) crush::add_contact(sum, c, d, U0 + pos);
    return dt_factor * crush::critical_step(mass, sum);
  };
  const double dt0 = step_at(0.0);
  double f = force(x);
  for (int n = 0; n < steps; n++) {
    const double dt = adaptive ? step_at(x) : dt0;
    v += 0.5 * dt * f / mass;
    x += dt * v;
    f = force(x);
    v += 0.5 * dt * f / mass;
    largest = std::max(largest, std::fabs(x));
    if (!(largest < 1.0)) break;
  }
  return largest;
}
}  // namespace

TEST(CriticalStep, OneHertzMindlinContactByHand)
{
  // Two equal balls: Dt = d/2; translational stiffness 1.5 k_N + k_S, rotation with I = 0.4 m r^2.
  const auto c = crush::hertz_mindlin_coefficients(kQuartz, kQuartz);
  const double d = 0.2e-3, U = 2e-7, mass = 1e-8;
  crush::ContactStiffness sum;
  crush::add_contact(sum, c, 0.5 * d, U);
  const double kN = c.normal * std::sqrt(0.5 * d * U), kS = c.shear * std::sqrt(0.5 * d * U);
  EXPECT_DOUBLE_EQ(sum.translational, 1.5 * kN + kS);
  EXPECT_DOUBLE_EQ(sum.shear, kS);
  const double expected = std::min(std::sqrt(mass / (1.5 * kN + kS)), std::sqrt(0.4 * mass / kS));
  EXPECT_DOUBLE_EQ(crush::critical_step(mass, sum), expected);
  // Four times the overlap: Hertz stiffens as sqrt(U), the step shrinks by 2^(1/2).
  crush::ContactStiffness deeper;
  crush::add_contact(deeper, c, 0.5 * d, 4.0 * U);
  EXPECT_NEAR(crush::critical_step(mass, sum) / crush::critical_step(mass, deeper), std::sqrt(2.0), 1e-12);
}

TEST(CriticalStep, NoContactsNoLimit)
{
  EXPECT_EQ(crush::critical_step(1e-8, crush::ContactStiffness()), 1e300);
}

TEST(CriticalStep, GrowsSlowlyShrinksAtOnceCapped)
{
  EXPECT_DOUBLE_EQ(crush::next_time_step(1e-8, 1e-7, 0.5, 1.01, 1.0), 1.01e-8);
  EXPECT_DOUBLE_EQ(crush::next_time_step(1e-8, 1e-8, 0.5, 1.01, 1.0), 0.5e-8);
  EXPECT_DOUBLE_EQ(crush::next_time_step(1e-8, 1e-7, 0.5, 10.0, 2e-8), 2e-8);
}

TEST(CriticalStep, StableBelowUnstableAboveForABallBetweenWalls)
{
  // Below the critical step the oscillation keeps its amplitude (0.2 U0); at three times it the
  // central-difference scheme diverges until the ball leaves a wall (the excursion exceeds U0; Hertz
  // then bounds it): the estimate is on the right side of the stability limit.
  const double U0 = 1e-7;
  EXPECT_LT(largest_excursion(0.5, true, 20000), 0.21 * U0);
  EXPECT_LT(largest_excursion(0.9, false, 20000), 0.21 * U0);
  EXPECT_GT(largest_excursion(3.0, false, 20000), U0);
}

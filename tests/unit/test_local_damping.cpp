// PFC local damping law, component by component.
#include <gtest/gtest.h>

#include <cmath>

#include "local_damping_law.h"

using crush::locally_damped;

TEST(LocalDamping, RemovesAlphaOfTheForceWhenItDrivesTheMotion)
{
  EXPECT_DOUBLE_EQ(locally_damped(10.0, 2.0, 0.05), 9.5);
  EXPECT_DOUBLE_EQ(locally_damped(-10.0, -2.0, 0.05), -9.5);
}

TEST(LocalDamping, AddsAlphaOfTheForceWhenItOpposesTheMotion)
{
  EXPECT_DOUBLE_EQ(locally_damped(-10.0, 2.0, 0.05), -10.5);
  EXPECT_DOUBLE_EQ(locally_damped(10.0, -2.0, 0.05), 10.5);
}

TEST(LocalDamping, NoVelocityNoDamping)
{
  EXPECT_DOUBLE_EQ(locally_damped(10.0, 0.0, 0.7), 10.0);
  EXPECT_DOUBLE_EQ(locally_damped(0.0, 3.0, 0.7), 0.0);
}

TEST(LocalDamping, BranchFreeFormIsExactlyPfcsRule)
{
  // F - alpha |F| where v > 0, F + alpha |F| where v < 0, F where v = 0 (or is not a number): to the
  // bit, over forces and velocities of every sign and scale.
  const double values[] = {-3.7e5, -1.0, -2.5e-12, 0.0, 4.2e-9, 1.0, 6.1e7};
  const double alpha = 0.05;
  for (double f : values)
    for (double v : values) {
      const double magnitude = f < 0.0 ? -f : f;
      const double expected = v > 0.0 ? f - alpha * magnitude : v < 0.0 ? f + alpha * magnitude : f;
      EXPECT_EQ(locally_damped(f, v, alpha), expected) << "F " << f << " v " << v;
    }
  EXPECT_EQ(locally_damped(2.0, std::nan(""), alpha), 2.0);
}

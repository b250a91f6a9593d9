// PFC local damping law, component by component.
#include <gtest/gtest.h>

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

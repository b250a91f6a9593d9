// PFC servo step with a stiffness-scaled gain.
#include <gtest/gtest.h>

#include <cmath>

#include "servo_wall_law.h"

using crush::servo_step;

TEST(ServoWall, NewtonStepOnTheWallForce)
{
  // 10 N short of the target on contacts of total stiffness 1e5 N/m: half of the 1e-4 m needed.
  EXPECT_DOUBLE_EQ(servo_step(90.0, 100.0, 1e5, 0.5, 1.0), 5e-5);
  // Too much force: the wall backs off.
  EXPECT_DOUBLE_EQ(servo_step(110.0, 100.0, 1e5, 0.5, 1.0), -5e-5);
}

TEST(ServoWall, CappedAndAdvancingWithoutContacts)
{
  EXPECT_DOUBLE_EQ(servo_step(0.0, 100.0, 1.0, 0.5, 1e-6), 1e-6);
  EXPECT_DOUBLE_EQ(servo_step(1e9, 100.0, 1.0, 0.5, 1e-6), -1e-6);
  EXPECT_DOUBLE_EQ(servo_step(0.0, 100.0, 0.0, 0.5, 1e-6), 1e-6);
}

TEST(ServoWall, ConvergesOnAHertzianSampleAcrossFiveDecades)
{
  // A wall on N Hertzian contacts, F = c U^1.5: iterate the servo at targets from 1 kPa to 100 MPa
  // equivalent forces; the relative error after 50 steps is below 1e-6 at every level.
  const double c = 1e9;
  for (double target : {1e-3, 1e-1, 1e1, 1e3}) {
    double U = 0.0;
    for (int step = 0; step < 200; ++step) {
      const double F = c * std::pow(U, 1.5);
      const double k = 1.5 * c * std::sqrt(U);
      U += servo_step(F, target, k, 0.5, 1e-6);
    }
    EXPECT_NEAR(c * std::pow(U, 1.5) / target, 1.0, 1e-6) << target;
  }
}

TEST(ServoWall, FeedForwardRemovesTheLagBehindARamp)
{
  // Hertzian wall contacts, target force growing by 1e-3 per step: after 2000 steps the lag is
  // dF/alpha without feed-forward and far smaller with it.
  const double c = 1e9, alpha = 0.05, rate = 1e-3;
  auto track = [&](bool feed_forward) {
    double U = std::pow(1.0 / c, 2.0 / 3.0), target = 1.0;
    for (int step = 0; step < 2000; ++step) {
      const double increment = rate * target;
      target += increment;
      const double F = c * std::pow(U, 1.5), k = 1.5 * c * std::sqrt(U);
      U += servo_step(F, target, k, alpha, 1.0, feed_forward ? increment : 0.0);
    }
    return c * std::pow(U, 1.5) / target - 1.0;
  };
  EXPECT_NEAR(track(false), -rate / alpha, 0.2 * rate / alpha);  // about -2%
  EXPECT_LT(std::fabs(track(true)), 1e-3);
}

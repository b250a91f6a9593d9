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

TEST(ServoWall, SampleStiffnessFeedForwardFollowsARampOnASoftSample)
{
  // The wall's contacts (stiffness kw) rest on a sample 20 times softer: quasi-statically the wall
  // force is K x. Fed forward with kw the wall lags by dF (kw/K - 1)/alpha (about 19 increments /
  // alpha); with the estimated sample stiffness the lag vanishes.
  const double kw = 2e7, K = 1e6, alpha = 0.5, rate = 1e-3;
  auto track = [&](bool estimate) {
    double x = 1e-6, target = K * x;
    crush::StiffnessEstimate sample;
    double last_force = K * x, last_move = 0.0;
    for (int step = 0; step < 3000; ++step) {
      const double increment = rate * target;
      target += increment;
      const double F = K * x;
      sample.add(F - last_force, last_move);
      last_force = F;
      last_move = servo_step(F, target, kw, alpha, 1.0, increment, estimate ? sample.value(kw) : kw);
      x += last_move;
    }
    return K * x / target - 1.0;
  };
  EXPECT_NEAR(track(false), -rate * (kw / K - 1.0) / alpha, 0.1 * rate * (kw / K) / alpha);  // about -4%
  EXPECT_LT(std::fabs(track(true)), 1e-3);
}

TEST(ServoWall, StiffnessEstimateIsBounded)
{
  crush::StiffnessEstimate k(0.5);
  EXPECT_DOUBLE_EQ(k.value(1e7), 1e7);  // no history yet
  for (int n = 0; n < 50; ++n) k.add(2.0, 1e-6);
  EXPECT_NEAR(k.value(1e7), 2e6, 1.0);
  for (int n = 0; n < 50; ++n) k.add(1.0, 1e-3);
  EXPECT_DOUBLE_EQ(k.value(1e7), 1e4);  // floor: 1e-3 kw
  for (int n = 0; n < 50; ++n) k.add(-1.0, 1e-6);
  EXPECT_DOUBLE_EQ(k.value(1e7), 1e7);  // force falling as the wall advances: back to kw
}

TEST(ServoWall, DriftRemovesTheLagOnADilatingSample)
{
  // Constant target on a linear sample whose unloaded surface recedes by v per step (dilation): the
  // proportional servo lags by v kw / alpha, the drift term (PI) removes the lag.
  const double kw = 1e6, alpha = 0.5, v = 1e-9, target = 1.0;
  auto track = [&](bool drift) {
    double x = target / kw, surface = 0.0, F = target;
    crush::DriftEstimate average;
    for (int step = 0; step < 5000; ++step) {
      surface += v;
      F = kw * (x - surface);  // the force the servo sees
      double dx = servo_step(F, target, kw, alpha, 1.0) + (drift ? average.value() : 0.0);
      average.add(dx);
      x += dx;
    }
    return F / target - 1.0;
  };
  EXPECT_NEAR(track(false), -v * kw / alpha / target, 1e-6);  // -0.2%
  EXPECT_LT(std::fabs(track(true)), 1e-6);
}

// Drained shearing at constant p': the lateral axes share 3 p' - sigma_axial, so the mean of the
// three stresses stays p' whatever the axial stress; with every axis in mode mean each carries p'.
TEST(ServoWall, MeanStressTargetKeepsTheMeanStress)
{
  const double p = 2e6;
  for (double sigma_axial : {2e6, 3.1e6, 4.7e6}) {
    const double lateral = crush::mean_stress_target(p, sigma_axial, 2);
    EXPECT_NEAR((sigma_axial + 2.0 * lateral) / 3.0, p, 1e-9 * p);
  }
  EXPECT_DOUBLE_EQ(crush::mean_stress_target(p, 0.0, 3), p);
  EXPECT_DOUBLE_EQ(crush::mean_stress_target(p, 2.5e6 + 1.5e6, 1), 2e6);
  // an axial stress above 3 p' would need tension from smooth walls: none
  EXPECT_EQ(crush::mean_stress_target(p, 7e6, 2), 0.0);
}

// Load ramp, eq. 11: step count from 1 kPa to 100 MPa and a closed-form bound.
#include <gtest/gtest.h>

#include <cmath>

#include "crush_load_ramp.h"
#include "crush_model_error.h"

using namespace crush;

namespace {
// I = integral of d sigma / increment(sigma) from s0 to s1. With t = 1 + ln(sigma/sigma_ref) it is
// (1/L_R) integral of e^(t-1)/t dt, evaluated by Simpson's rule (smooth integrand, 2e5 intervals).
double continuous_steps(double L, double ref, double s0, double s1)
{
  const double t0 = 1.0 + std::log(s0 / ref), t1 = 1.0 + std::log(s1 / ref);
  const int n = 200000;
  const double h = (t1 - t0) / n;
  auto f = [](double t) { return std::exp(t - 1.0) / t; };
  double sum = f(t0) + f(t1);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(t0 + i * h);
  return sum * h / 3.0 / L;
}
}  // namespace

TEST(LoadRamp, IncrementIsEq11InKilopascals)
{
  const LoadRamp ramp(0.1);
  // At sigma = sigma_ref = 1 kPa: L_R [1 + ln 1] kPa = 0.1 kPa.
  EXPECT_DOUBLE_EQ(ramp.increment(1e3), 100.0);
  // At 1 MPa: 0.1 [1 + ln 1000] kPa = 0.79078 kPa.
  EXPECT_NEAR(ramp.increment(1e6), 100.0 * (1.0 + std::log(1000.0)), 1e-9);
  EXPECT_NEAR(ramp.next(1e6), 1e6 + 790.7755279, 1e-6);
}

TEST(LoadRamp, StepsFrom1kPaTo100MPa)
{
  const LoadRamp ramp(0.1);
  const long n = ramp.steps_to_reach(1e3, 1e8);
  EXPECT_EQ(n, 87713);
  // Bound: the increment grows with sigma, so each step covers at most one unit of I, giving n >= I;
  // and a step covers at least f(s_i)/f(s_i+1) >= 1 - L_R sigma_ref/s_i units, whose deficits sum
  // to at most ln(1 + ln(s1/sigma_ref)) + L_R < 3 over the ramp: n <= I + 1 + 3.
  const double I = continuous_steps(0.1, 1e3, 1e3, 1e8);
  EXPECT_GE(n, I);
  EXPECT_LE(n, I + 4.0);
  // Halving the load rate doubles the steps (to within the same bound).
  const long n_half = LoadRamp(0.05).steps_to_reach(1e3, 1e8);
  EXPECT_GE(n_half, 2.0 * I);
  EXPECT_LE(n_half, 2.0 * I + 4.0);
}

TEST(LoadRamp, InvalidInput)
{
  EXPECT_THROW(LoadRamp(0.0), ModelError);
  EXPECT_THROW(LoadRamp(0.1, -1.0), ModelError);
  EXPECT_THROW(LoadRamp(0.1).increment(0.0), ModelError);
  EXPECT_THROW(LoadRamp(0.1).steps_to_reach(100.0, 1e8), ModelError);  // below sigma_ref/e
}

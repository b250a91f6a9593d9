// Grading: percent passing with fractal fines, downscaling, and the grading index I_G.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "crush_grading.h"
#include "crush_model_error.h"

using namespace crush;

TEST(Grading, FractalDistributionMatchesItsClosedForm)
{
  // Grains sampled from a fractal grading of dimension D = 2.5 (inverse CDF of the mass fraction
  // passing (d/d_max)^0.5, each grain carrying equal mass) reproduce it at every sieve.
  const double d_max = 1e-3, D = 2.5;
  const std::vector<double> sieves{0.01e-3, 0.05e-3, 0.1e-3, 0.3e-3, 0.6e-3, 0.9e-3};
  const Grading grading(sieves, 1.0, D);
  GradingSums sums = grading.empty_sums();
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double F = (i + 0.5) / n;
    grading.add_volume(d_max * F * F, 1.0, sums);  // inverse of F = (d/d_max)^0.5, equal masses
  }
  const auto passing = grading.percent_passing(sums, 0.0, 0.0);
  for (std::size_t k = 0; k < sieves.size(); ++k)
    EXPECT_NEAR(passing[k], 100.0 * fractal_passing(sieves[k], d_max, D), 0.02) << sieves[k];
  // And it is the limiting grading: I_G = 1.
  EXPECT_NEAR(grading.grading_index(sums, 0.0, 0.0, d_max), 1.0, 1e-3);
}

TEST(Grading, SingleSizeSampleIsAStep)
{
  const std::vector<double> sieves{0.1e-3, 0.2e-3, 0.2500001e-3, 0.3e-3};
  const Grading grading(sieves, 1.0);
  GradingSums sums = grading.empty_sums();
  for (int i = 0; i < 100; ++i) grading.add_grain(0.25e-3, sums);
  const auto p = grading.percent_passing(sums, 0.0, 0.0);
  EXPECT_EQ(p[0], 0.0);
  EXPECT_EQ(p[1], 0.0);
  EXPECT_DOUBLE_EQ(p[2], 100.0);
  EXPECT_DOUBLE_EQ(p[3], 100.0);
  // A single size at d_max has I_G = 0.
  EXPECT_NEAR(grading.grading_index(sums, 0.0, 0.0, 0.25e-3), 0.0, 1e-12);
}

TEST(Grading, DownscalingDividesSizesByN)
{
  const std::vector<double> sieves{0.2e-3, 0.3e-3};
  const Grading scaled(sieves, 2.0);
  GradingSums sums = scaled.empty_sums();
  scaled.add_grain(0.5e-3, sums);  // 0.25 mm once downscaled by N = 2
  const auto p = scaled.percent_passing(sums, 0.0, 0.0);
  EXPECT_EQ(p[0], 0.0);
  EXPECT_DOUBLE_EQ(p[1], 100.0);
}

TEST(Grading, RemovedVolumeMovesMassBelowTheSmallestFragmentOnly)
{
  const std::vector<double> sieves{0.01e-3, 0.04e-3, 0.08e-3, 0.1e-3, 0.2e-3, 0.3e-3};
  const Grading grading(sieves, 1.0, 2.5);
  GradingSums sums = grading.empty_sums();
  grading.add_grain(0.25e-3, sums);
  const double v = sums.volume;
  const double removed = 0.5 * v, d_f = 0.08e-3;
  const auto p = grading.percent_passing(sums, removed, d_f);
  const double fines_share = 100.0 * removed / (v + removed);
  EXPECT_NEAR(p[0], fines_share * std::sqrt(0.01 / 0.08), 1e-9);
  EXPECT_NEAR(p[1], fines_share * std::sqrt(0.04 / 0.08), 1e-9);
  // At and above d_f all fines pass, nothing else does below the grain size.
  EXPECT_NEAR(p[2], fines_share, 1e-9);
  EXPECT_NEAR(p[3], fines_share, 1e-9);
  EXPECT_NEAR(p[4], fines_share, 1e-9);
  EXPECT_DOUBLE_EQ(p[5], 100.0);
}

TEST(Grading, GradingIndexOfAFontainebleauLikeGradingIsAboutThePapers)
{
  // A uniform sand with d50 = 0.21 mm: mass uniformly distributed on log d between 0.097 and
  // 0.455 mm (d10 = 0.113, d50 = 0.210, d90 = 0.390 mm). The paper reports I_G = 0.735 initially.
  const double d_lo = 0.097e-3, d_hi = 0.455e-3;
  const Grading grading({0.21e-3}, 1.0, 2.5);
  GradingSums sums = grading.empty_sums();
  const int n = 20000;
  for (int i = 0; i < n; ++i) grading.add_volume(d_lo * std::pow(d_hi / d_lo, (i + 0.5) / n), 1.0, sums);
  EXPECT_NEAR(grading.percent_passing(sums, 0.0, 0.0)[0],
              100.0 * std::log(0.21 / 0.097) / std::log(0.455 / 0.097), 0.01);
  // Linear-axis areas: I_G = 1.5 (1 - mean size / d_max), mean size = (d_hi - d_lo)/ln(d_hi/d_lo)
  // = 0.2316 mm: I_G = 0.7365.
  const double mean = (d_hi - d_lo) / std::log(d_hi / d_lo);
  EXPECT_NEAR(grading.grading_index(sums, 0.0, 0.0, d_hi), 1.5 * (1.0 - mean / d_hi), 1e-6);
  EXPECT_NEAR(grading.grading_index(sums, 0.0, 0.0, d_hi), 0.735, 0.005);
}

TEST(Grading, CrushingRaisesTheGradingIndex)
{
  const Grading grading({0.1e-3}, 1.0, 2.5);
  GradingSums sums = grading.empty_sums();
  grading.add_grain(0.3e-3, sums);
  const double before = grading.grading_index(sums, 0.0, 0.0, 0.3e-3);
  const double after = grading.grading_index(sums, 0.2 * sums.volume, 0.05e-3, 0.3e-3);
  EXPECT_GT(after, before);
  // By hand: area = [0 + 0.2 V (0.05/1.5 + 0.3 - 0.05) mm] / 1.2 V; limit area 0.3/1.5 = 0.2 mm.
  EXPECT_NEAR(after, 0.2 * (0.05 / 1.5 + 0.25) / 1.2 / 0.2, 1e-12);
}

TEST(Grading, InvalidInput)
{
  EXPECT_THROW(Grading({0.2e-3, 0.1e-3}, 1.0), ModelError);
  EXPECT_THROW(Grading({0.1e-3}, 0.0), ModelError);
  EXPECT_THROW(Grading({0.1e-3}, 1.0, 3.0), ModelError);
  EXPECT_THROW(Grading({-0.1e-3}, 1.0), ModelError);
  const Grading g({0.1e-3}, 1.0);
  EXPECT_THROW(g.percent_passing(g.empty_sums(), 0.0, 0.0), ModelError);
  EXPECT_THROW(g.percent_passing(g.empty_sums(), -1.0, 0.0), ModelError);
}

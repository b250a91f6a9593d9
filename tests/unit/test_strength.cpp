// Strength draws: distributions, determinism per (seed, tag), independence between tags.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "crush_model_error.h"
#include "crush_random.h"
#include "crush_strength.h"

using namespace crush;

namespace {
struct Moments {
  double mean, cv;
};

Moments sample_moments(const StrengthDraw &draw, int n, std::uint64_t first_tag = 1, bool zeros = false)
{
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double s = draw.draw(first_tag + i);
    if (zeros) EXPECT_GE(s, 0.0);
    else EXPECT_GT(s, 0.0);
    sum += s;
    sum2 += s * s;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(sum2 / n - mean * mean) / mean};
}
}  // namespace

TEST(TruncatedNormal, ClosedFormMatchesKnownValues)
{
  // N(1,1) truncated at 0: alpha = -1, lambda = phi(-1)/(1-Phi(-1)) = 0.2419707/0.8413447 = 0.2875999.
  EXPECT_NEAR(truncated_normal_mean(1.0, 1.0), 1.2875999, 1e-6);
  // variance = 1 + alpha lambda - lambda^2 = 1 - 0.2876 - 0.0827137 = 0.6296864.
  EXPECT_NEAR(truncated_normal_cv(1.0, 1.0), std::sqrt(0.6296864) / 1.2875999, 1e-6);
  // Far from the truncation point nothing changes.
  EXPECT_NEAR(truncated_normal_mean(1.0, 0.1), 1.0, 1e-12);
  EXPECT_NEAR(truncated_normal_cv(1.0, 0.1), 0.1, 1e-10);
}

TEST(StrengthDraw, TruncatedNormalWithPaperCvReproducesItsMoments)
{
  // Table 1: sigma_lim0 = 5e6 kPa, CV = 1.
  const StrengthDraw draw(StrengthDistribution::normal, 5e9, 1.0, 10.0, 1234567);
  const Moments m = sample_moments(draw, 100000);
  EXPECT_NEAR(m.mean / draw.mean(), 1.0, 0.01);
  EXPECT_NEAR(m.cv / draw.cv(), 1.0, 0.01);
  EXPECT_NEAR(draw.mean(), 1.2876 * 5e9, 1e-4 * 5e9);
}

TEST(StrengthDraw, ClippedNormalWithPaperCvIsZeroOneTimeInSix)
{
  // The plain normal of Table 1 (CV = 1), negative draws clipped to 0: P(s = 0) = Phi(-1) = 0.1587,
  // mean = mu Phi(1) + sigma phi(1) = 1.0833 mu, the rest as drawn.
  const StrengthDraw draw(StrengthDistribution::normal_clipped, 5e9, 1.0, 10.0, 1234567);
  const Moments m = sample_moments(draw, 100000, 1, true);
  int zeros = 0;
  for (std::uint64_t tag = 1; tag <= 100000; ++tag) zeros += draw.draw(tag) == 0.0;
  EXPECT_NEAR(zeros / 1e5, 0.158655, 0.004);
  EXPECT_NEAR(draw.mean(), (0.841345 + 0.241971) * 5e9, 1e-5 * 5e9);
  EXPECT_NEAR(m.mean / draw.mean(), 1.0, 0.01);
  EXPECT_NEAR(m.cv / draw.cv(), 1.0, 0.01);
}

TEST(StrengthDraw, NormalWithSmallCvIsThePlainNormal)
{
  const StrengthDraw draw(StrengthDistribution::normal, 2e9, 0.2, 10.0, 99);
  const Moments m = sample_moments(draw, 100000);
  EXPECT_NEAR(m.mean / 2e9, 1.0, 0.01);
  EXPECT_NEAR(m.cv / 0.2, 1.0, 0.01);
}

TEST(StrengthDraw, WeibullHasMeanSigmaLim0AndCvFromModulus)
{
  const StrengthDraw draw(StrengthDistribution::weibull, 5e9, 1.0, 10.0, 7);
  // CV of a Weibull with modulus 10: sqrt(G(1.2)/G(1.1)^2 - 1) = 0.12025.
  EXPECT_NEAR(draw.cv(), 0.12025, 1e-4);
  const Moments m = sample_moments(draw, 100000);
  EXPECT_NEAR(m.mean / 5e9, 1.0, 0.01);
  EXPECT_NEAR(m.cv / draw.cv(), 1.0, 0.01);
}

TEST(StrengthDraw, ConstantIsSigmaLim0)
{
  const StrengthDraw draw(StrengthDistribution::constant, 3e9, 1.0, 10.0, 7);
  EXPECT_EQ(draw.draw(1), 3e9);
  EXPECT_EQ(draw.draw(123456789), 3e9);
  EXPECT_EQ(draw.cv(), 0.0);
}

TEST(StrengthDraw, SameSeedAndTagGiveTheSameValueWhateverWasDrawnBefore)
{
  const StrengthDraw a(StrengthDistribution::normal, 5e9, 1.0, 10.0, 42);
  const StrengthDraw b(StrengthDistribution::normal, 5e9, 1.0, 10.0, 42);
  const double first = a.draw(777);
  for (std::uint64_t t = 1; t < 1000; ++t) b.draw(t);  // b has drawn many other tags first
  EXPECT_EQ(b.draw(777), first);
  EXPECT_EQ(a.draw(777), first);
  const StrengthDraw other_seed(StrengthDistribution::normal, 5e9, 1.0, 10.0, 43);
  EXPECT_NE(other_seed.draw(777), first);
}

TEST(StrengthDraw, NeighbouringTagsAreUncorrelated)
{
  const StrengthDraw draw(StrengthDistribution::normal, 1.0, 0.3, 10.0, 2024);
  const int n = 100000;
  std::vector<double> s(n + 1);
  for (int i = 0; i <= n; ++i) s[i] = draw.draw(i + 1);
  double mean = 0.0;
  for (double x : s) mean += x;
  mean /= s.size();
  double cov = 0.0, var = 0.0;
  for (int i = 0; i < n; ++i) {
    cov += (s[i] - mean) * (s[i + 1] - mean);
    var += (s[i] - mean) * (s[i] - mean);
  }
  // The lag-1 correlation of n independent draws has standard deviation 1/sqrt(n) = 0.0032.
  EXPECT_LT(std::fabs(cov / var), 0.0032 * 4);
}

TEST(RandomStreams, UniformsAreUniformAndStreamsDiffer)
{
  const int n = 100000, bins = 10;
  std::vector<int> count(bins, 0);
  for (int i = 0; i < n; ++i) {
    const double u = uniform_open(5, i, Stream::orientation, 0);
    ASSERT_GT(u, 0.0);
    ASSERT_LT(u, 1.0);
    ++count[static_cast<int>(u * bins)];
  }
  double chi2 = 0.0;
  for (int c : count) chi2 += (c - n / bins) * double(c - n / bins) / (n / bins);
  EXPECT_LT(chi2, 27.88);  // chi^2 with 9 degrees of freedom, p = 0.001
  EXPECT_NE(hash_draw(5, 9, Stream::strength, 0), hash_draw(5, 9, Stream::orientation, 0));
}

TEST(StrengthDraw, InvalidInputNamesTheParameter)
{
  EXPECT_THROW(StrengthDraw(StrengthDistribution::normal, 0.0, 1.0, 10.0, 1), ModelError);
  EXPECT_THROW(StrengthDraw(StrengthDistribution::normal, 5e9, -0.1, 10.0, 1), ModelError);
  EXPECT_THROW(StrengthDraw(StrengthDistribution::weibull, 5e9, 1.0, 0.0, 1), ModelError);
  try {
    StrengthDraw(StrengthDistribution::normal, 5e9, -1.0, 10.0, 1);
  } catch (const ModelError &e) {
    EXPECT_NE(std::string(e.what()).find("cv"), std::string::npos);
  }
}

TEST(StrengthDraw, ClippedOriginalsTruncatedFragments)
{
  // Table 3's reading: original grains draw the clipped normal (zero one time in six for CV = 1),
  // fragments the truncated normal (never zero), each the same draw as the plain distribution.
  const StrengthDraw mixed(StrengthDistribution::normal_clipped_originals, 5e9, 1.0, 10.0, 1234567);
  const StrengthDraw clipped(StrengthDistribution::normal_clipped, 5e9, 1.0, 10.0, 1234567);
  const StrengthDraw truncated(StrengthDistribution::normal, 5e9, 1.0, 10.0, 1234567);
  int zeros = 0, fragment_zeros = 0;
  for (std::uint64_t tag = 1; tag <= 100000; ++tag) {
    const double original = mixed.draw(tag, 0), fragment = mixed.draw(tag, 1);
    ASSERT_EQ(original, clipped.draw(tag));
    ASSERT_EQ(fragment, truncated.draw(tag));
    ASSERT_EQ(mixed.draw(tag, 3), fragment);
    zeros += original == 0.0;
    fragment_zeros += fragment <= 0.0;
  }
  EXPECT_NEAR(zeros / 1e5, 0.158655, 0.004);
  EXPECT_EQ(fragment_zeros, 0);
  EXPECT_EQ(mixed.mean(), clipped.mean());
}

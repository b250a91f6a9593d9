// fix crush keywords: defaults, values, and errors that name the keyword.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "crush_model_error.h"
#include "crush_number.h"
#include "crush_settings.h"

using namespace crush;

namespace {
const std::vector<std::string> required{"sigma_lim0", "5e9", "cv", "1", "weibull_m", "10",
                                        "d0", "2e-3", "seed", "1234567"};

std::string error_of(std::vector<std::string> args)
{
  try {
    parse_crush_settings(args);
  } catch (const ModelError &e) {
    return e.what();
  }
  return "";
}

std::vector<std::string> with(std::vector<std::string> extra)
{
  std::vector<std::string> args = required;
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}
}  // namespace

TEST(CrushSettings, RequiredAndDefaults)
{
  const CrushSettings c = parse_crush_settings(required);
  EXPECT_EQ(c.sigma_lim0, 5e9);
  EXPECT_EQ(c.cv, 1.0);
  EXPECT_EQ(c.weibull_m, 10.0);
  EXPECT_EQ(c.d0, 2e-3);
  EXPECT_EQ(c.seed, 1234567u);
  EXPECT_EQ(c.scale_factor, 1.0);
  EXPECT_EQ(c.dmin, 0.0);
  EXPECT_EQ(c.every, 1);
  EXPECT_FALSE(c.adaptive);
  EXPECT_TRUE(c.random_orientation);
  EXPECT_EQ(c.distribution, StrengthDistribution::normal);
  EXPECT_TRUE(c.size_effect);
  EXPECT_EQ(c.layout, FragmentLayout::fourteen);
  EXPECT_EQ(c.fines_dimension, 2.5);
  EXPECT_TRUE(c.log_file.empty());
}

TEST(CrushSettings, OptionalKeywords)
{
  const CrushSettings c = parse_crush_settings(
      with({"scale", "2", "dmin", "5e-5", "every", "10", "orientation", "fixed", "distribution", "weibull",
            "size_effect", "no", "layout", "tetrahedral", "fines_dimension", "2.6", "log", "ev.csv"}));
  EXPECT_EQ(c.scale_factor, 2.0);
  EXPECT_EQ(c.dmin, 5e-5);
  EXPECT_EQ(c.every, 10);
  EXPECT_FALSE(c.random_orientation);
  EXPECT_EQ(c.distribution, StrengthDistribution::weibull);
  EXPECT_FALSE(c.size_effect);
  EXPECT_EQ(c.layout, FragmentLayout::tetrahedral);
  EXPECT_EQ(c.fines_dimension, 2.6);
  EXPECT_EQ(c.log_file, "ev.csv");
  // size_effect no: sigma_lim = s whatever the size.
  EXPECT_EQ(c.size_scaled(3e9, 1e-4), 3e9);
}

TEST(CrushSettings, SizeScaledUsesEq10WithN)
{
  const CrushSettings c = parse_crush_settings(with({"scale", "2"}));
  // d = N d0: no correction.
  EXPECT_DOUBLE_EQ(c.size_scaled(5e9, 4e-3), 5e9);
}

// Eq. 10 per grain ('scale_atom'): sigma_lim = s (d/(N_i d0))^(-3/m) with each particle's own N_i,
// whatever the deck's N; the deck's N is the per-grain form at N_i = N.
TEST(CrushSettings, SizeScaledPerGrain)
{
  const CrushSettings c = parse_crush_settings(with({"scale", "80", "scale_atom", "grain_scale"}));
  EXPECT_EQ(c.scale_atom, "grain_scale");
  const double s = 5e9, d0 = 2e-3, m = 10.0;
  for (double n : {17.0, 34.0, 80.0})
    for (double d : {1e-3, 7e-3, 2.1e-2})
      EXPECT_NEAR(c.size_scaled(s, d, n), s * std::pow(d / (n * d0), -3.0 / m), 1e-12 * s) << "N " << n << " d " << d;
  EXPECT_EQ(c.size_scaled(s, 5e-3, 80.0), c.size_scaled(s, 5e-3));
  // Two model grains that stand for the same sand grain (d / N equal) have the same strength...
  EXPECT_NEAR(c.size_scaled(s, 17 * 0.21e-3, 17.0), c.size_scaled(s, 80 * 0.21e-3, 80.0), 1e-12 * s);
  // ...and a grain of the fine zone (N = 17) is weaker than the same model size at N = 80 by (80/17)^(-3/m).
  EXPECT_NEAR(c.size_scaled(s, 5e-3, 17.0) / c.size_scaled(s, 5e-3, 80.0), std::pow(80.0 / 17.0, -0.3), 1e-12);
  // size_effect no: sigma_lim = s for every N.
  const CrushSettings flat = parse_crush_settings(with({"size_effect", "no", "scale_atom", "grain_scale"}));
  EXPECT_EQ(flat.size_scaled(s, 5e-3, 17.0), s);
}

TEST(CrushSettings, ErrorsNameTheKeywordAndTheExpectedValue)
{
  EXPECT_NE(error_of({"cv", "1"}).find("'sigma_lim0' is required"), std::string::npos);
  EXPECT_NE(error_of(with({"cv", "-1"})).find("'cv' expects a coefficient of variation in [0, 10]"), std::string::npos);
  EXPECT_NE(error_of(with({"weibull_m", "0"})).find("'weibull_m'"), std::string::npos);
  EXPECT_NE(error_of(with({"d0", "abc"})).find("got 'abc'"), std::string::npos);
  EXPECT_NE(error_of(with({"scale", "0"})).find("'scale' expects an upscaling factor N in (0, 1e4]"), std::string::npos);
  EXPECT_NE(error_of(with({"dmin", "-1"})).find("'dmin'"), std::string::npos);
  EXPECT_NE(error_of(with({"every", "1.5"})).find("'every' expects an integer >= 1 or 'adaptive', got '1.5'"),
            std::string::npos);
  EXPECT_NE(error_of(with({"every", "0"})).find("got '0'"), std::string::npos);
  // beyond an int's range: the step counter is an int
  EXPECT_NE(error_of(with({"every", "2e9"})).find("got '2e9'"), std::string::npos);
  EXPECT_NE(error_of(with({"every"})).find("'every' expects"), std::string::npos);
  EXPECT_TRUE(parse_crush_settings(with({"every", "adaptive"})).adaptive);
  EXPECT_NE(error_of(with({"orientation", "up"})).find("'random' or 'fixed'"), std::string::npos);
  EXPECT_NE(error_of(with({"distribution", "lognormal"})).find("'normal', 'normal_clipped', 'normal_clipped_originals', 'weibull' or 'constant'"),
            std::string::npos);
  EXPECT_NE(error_of(with({"size_effect", "maybe"})).find("'yes' or 'no'"), std::string::npos);
  EXPECT_NE(error_of(with({"fines_dimension", "3"})).find("'fines_dimension'"), std::string::npos);
  EXPECT_NE(error_of(with({"seed", "-5"})).find("'seed' expects a positive integer"), std::string::npos);
  EXPECT_NE(error_of(with({"speed", "3"})).find("unknown keyword 'speed'"), std::string::npos);
  EXPECT_NE(error_of(with({"log"})).find("'log' expects a file name"), std::string::npos);
}

// Physical ranges: the edges are accepted, values past them (1e-300, the issue's) are refused by name.
TEST(CrushSettings, RangesExcludeValuesWithoutPhysicalMeaning)
{
  auto with_value = [](const std::string &key, const std::string &value) {
    std::vector<std::string> args = required;
    for (std::size_t k = 0; k + 1 < args.size(); k += 2)
      if (args[k] == key) args[k + 1] = value;
    if (std::find(args.begin(), args.end(), key) == args.end()) args.insert(args.end(), {key, value});
    return args;
  };
  const struct {
    const char *key, *low, *high, *below, *above;
  } edges[] = {{"sigma_lim0", "1e3", "1e30", "1e-300", "1e31"}, {"cv", "0", "10", "-1e-9", "10.5"},
               {"weibull_m", "0.5", "1000", "1e-300", "1001"}, {"d0", "1e-7", "10", "1e-300", "11"},
               {"dmin", "0", "10", "-1e-300", "11"}, {"scale", "1e-300", "1e4", "0", "1.0001e4"},
               {"fines_dimension", "0", "2.999", "-0.1", "3"}};
  for (const auto &e : edges) {
    EXPECT_EQ(error_of(with_value(e.key, e.low)), "") << e.key << " " << e.low;
    EXPECT_EQ(error_of(with_value(e.key, e.high)), "") << e.key << " " << e.high;
    EXPECT_NE(error_of(with_value(e.key, e.below)).find(std::string("'") + e.key + "' expects"), std::string::npos) << e.key;
    EXPECT_NE(error_of(with_value(e.key, e.above)).find(std::string("'") + e.key + "' expects"), std::string::npos) << e.key;
  }
}

// Legal but unlikely values are named once each; the paper's values raise none.
TEST(CrushSettings, SuspiciousValuesAreWarnedOf)
{
  EXPECT_TRUE(suspicious_settings(parse_crush_settings(with({"scale", "2"}))).empty());
  const std::vector<std::string> w = suspicious_settings(parse_crush_settings(
      {"sigma_lim0", "5e3", "cv", "3", "weibull_m", "0.7", "d0", "2e-3", "seed", "1", "scale", "0.5",
       "fines_dimension", "1", "rayleigh_fraction", "0.9"}));
  ASSERT_EQ(w.size(), 6u);
  EXPECT_NE(w[0].find("sigma_lim0 5000 Pa is below 100 kPa"), std::string::npos) << w[0];
  EXPECT_NE(w[1].find("cv above 2"), std::string::npos);
  EXPECT_NE(w[2].find("weibull_m outside [1, 50]"), std::string::npos);
  EXPECT_NE(w[3].find("scale below 1"), std::string::npos);
  EXPECT_NE(w[4].find("fines_dimension below 2"), std::string::npos);
  EXPECT_NE(w[5].find("rayleigh_fraction above 0.5"), std::string::npos);
}

// Every numeric keyword rejects what strtod alone would take: inf, nan, overflow, trailing text.
TEST(CrushSettings, NumbersMustBeFinite)
{
  for (const char *key : {"sigma_lim0", "cv", "weibull_m", "d0", "seed", "scale", "dmin", "every", "fines_dimension",
                          "rayleigh_fraction"})
    for (const char *bad : {"inf", "-inf", "nan", "1e999", "5x"}) {
      const std::string message = error_of(with({key, bad}));
      EXPECT_NE(message.find(std::string("keyword '") + key + "' expects"), std::string::npos)
          << key << " " << bad << ": " << message;
      EXPECT_NE(message.find(std::string("got '") + bad + "'"), std::string::npos) << key << " " << bad;
    }
}

TEST(CrushSettings, CheckTagsIsASwitch)
{
  EXPECT_FALSE(parse_crush_settings(required).check_tags);
  EXPECT_TRUE(parse_crush_settings(with({"check_tags", "yes"})).check_tags);
  EXPECT_NE(error_of(with({"check_tags", "1"})).find("'check_tags' expects 'yes' or 'no'"), std::string::npos);
}

TEST(CrushSettings, FragmentDensityIsTrueUnlessScaled)
{
  EXPECT_EQ(parse_crush_settings(required).fragment_density, FragmentDensity::true_density);
  EXPECT_EQ(parse_crush_settings(with({"fragment_density", "scaled"})).fragment_density, FragmentDensity::scaled);
  EXPECT_EQ(parse_crush_settings(with({"fragment_density", "true"})).fragment_density, FragmentDensity::true_density);
  EXPECT_NE(error_of(with({"fragment_density", "yes"})).find("'fragment_density' expects 'true' or 'scaled', got 'yes'"),
            std::string::npos);
}

TEST(CrushSettings, RedrawIsOffUnlessAsked)
{
  EXPECT_FALSE(parse_crush_settings(required).redraw);
  EXPECT_TRUE(parse_crush_settings(with({"redraw", "yes"})).redraw);
  EXPECT_NE(error_of(with({"redraw", "all"})).find("'redraw' expects 'yes' or 'no'"), std::string::npos);
}

TEST(KeywordNumber, AcceptsFiniteNumbersOnly)
{
  double v = 0.0;
  EXPECT_TRUE(parse_finite("2.5e-3", v));
  EXPECT_EQ(v, 2.5e-3);
  EXPECT_TRUE(parse_finite("-7", v));
  EXPECT_EQ(v, -7.0);
  for (const char *bad : {"", "inf", "INF", "-Infinity", "nan", "NaN", "1e400", "-1e400", "3 ", "0x", "e5"})
    EXPECT_FALSE(parse_finite(bad, v)) << bad;
  EXPECT_EQ(v, -7.0);  // untouched by a rejected text
}

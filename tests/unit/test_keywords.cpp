// Keyword tables (crush_keywords.h): values stored, ranges enforced, and error texts generated from
// the table: the keyword, what it expects and what was given.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "crush_keywords.h"
#include "crush_model_error.h"

using namespace crush;

namespace {
struct Damping {
  double alpha = -1.0;
  bool moments = true;
  long every = 1;
  int mode = 0;
  std::string log;
};

std::string error_of(const KeywordTable &t, const std::vector<std::string> &args)
{
  try {
    t.parse(args);
  } catch (const ModelError &e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(KeywordTable, StoresEachKindOfValue)
{
  Damping d;
  KeywordTable t;
  t.number("alpha", "a value in [0, 1)", in_range(0.0, 1.0, false), d.alpha, true)
   .yes_no("moments", d.moments)
   .integer("every", "an integer >= 1", 1, d.every)
   .choice("mode", {"fixed", "ramp", "stress"}, d.mode)
   .text("log", "a file name", d.log);
  t.parse({"every", "20", "alpha", "0.05", "moments", "no", "mode", "stress", "log", "x.csv"});
  EXPECT_EQ(d.alpha, 0.05);
  EXPECT_FALSE(d.moments);
  EXPECT_EQ(d.every, 20);
  EXPECT_EQ(d.mode, 2);
  EXPECT_EQ(d.log, "x.csv");
  EXPECT_EQ(t.accepted(), "alpha, moments, every, mode or log");
  EXPECT_TRUE(t.is_keyword("mode"));
  EXPECT_FALSE(t.is_keyword("0.05"));
}

TEST(KeywordTable, ErrorsComeFromTheTable)
{
  Damping d;
  KeywordTable t;
  t.number("alpha", "a value in [0, 1)", in_range(0.0, 1.0, false), d.alpha, true)
   .integer("every", "an integer >= 1", 1, d.every)
   .choice("mode", {"fixed", "ramp", "stress"}, d.mode);
  EXPECT_EQ(error_of(t, {"alpha", "1"}), "keyword 'alpha' expects a value in [0, 1), got '1'");
  EXPECT_EQ(error_of(t, {"alpha", "nan"}), "keyword 'alpha' expects a value in [0, 1), got 'nan'");
  EXPECT_EQ(error_of(t, {"alpha"}), "keyword 'alpha' expects a value in [0, 1)");
  EXPECT_EQ(error_of(t, {"alpha", "0.1", "every", "2.5"}), "keyword 'every' expects an integer >= 1, got '2.5'");
  EXPECT_EQ(error_of(t, {"alpha", "0.1", "every", "0"}), "keyword 'every' expects an integer >= 1, got '0'");
  EXPECT_EQ(error_of(t, {"alpha", "0.1", "mode", "up"}),
            "keyword 'mode' expects 'fixed', 'ramp' or 'stress', got 'up'");
  EXPECT_EQ(error_of(t, {"alpha", "0.1", "speed", "3"}),
            "unknown keyword 'speed' (expected alpha, every or mode)");
  EXPECT_EQ(error_of(t, {"every", "3"}), "keyword 'alpha' is required (a value in [0, 1))");
  EXPECT_EQ(error_of(t, {"alpha", "0.5"}), "");
  EXPECT_EQ(d.alpha, 0.5);
}

// A list up to the next keyword (compute crush/gsd's sieves, fix wall/servo's outputs).
TEST(KeywordTable, AscendingListReadsUpToTheNextKeyword)
{
  std::vector<double> sieves;
  double dmax = 0.0;
  KeywordTable t;
  t.ascending("sieves", "ascending sizes > 0 (m)", sieves, true).number("dmax", "one size > 0 (m)", positive(), dmax);
  t.parse({"sieves", "1e-4", "2e-4", "3e-4", "dmax", "4e-4"});
  EXPECT_EQ(sieves, (std::vector<double>{1e-4, 2e-4, 3e-4}));
  EXPECT_EQ(dmax, 4e-4);
  sieves.clear();
  EXPECT_EQ(error_of(t, {"sieves", "2e-4", "1e-4"}), "keyword 'sieves' expects ascending sizes > 0 (m), got '1e-4'");
  sieves.clear();
  EXPECT_EQ(error_of(t, {"sieves", "-1"}), "keyword 'sieves' expects ascending sizes > 0 (m), got '-1'");
  sieves.clear();
  EXPECT_EQ(error_of(t, {"sieves", "dmax", "1"}), "keyword 'sieves' expects ascending sizes > 0 (m)");
}

// A reader of its own (as fix wall/servo's 'x stress S'): it says how many values it read.
TEST(KeywordTable, CustomReader)
{
  int mode = -1;
  double value = 0.0;
  KeywordTable t;
  t.add("x", "fixed or stress S (Pa)", [&](const std::vector<std::string> &w, std::size_t at) {
    if (at + 1 < w.size() && w[at + 1] == "fixed") {
      mode = 0;
      return std::size_t(1);
    }
    if (at + 1 >= w.size() || w[at + 1] != "stress") t.fail("x", at + 1 < w.size() ? w[at + 1] : "");
    mode = 1;
    value = t.value("x", w, at + 2);
    return std::size_t(2);
  });
  t.parse({"x", "stress", "1e5"});
  EXPECT_EQ(mode, 1);
  EXPECT_EQ(value, 1e5);
  t.parse({"x", "fixed"});
  EXPECT_EQ(mode, 0);
  EXPECT_EQ(error_of(t, {"x", "push"}), "keyword 'x' expects fixed or stress S (Pa), got 'push'");
}

TEST(KeywordTable, Ranges)
{
  EXPECT_TRUE(positive()(1e-300));
  EXPECT_FALSE(positive()(0.0));
  EXPECT_TRUE(at_least(0.0)(0.0));
  EXPECT_FALSE(below(3.0)(3.0));
  EXPECT_TRUE(in_range(0.0, 1.0, true)(1.0));
  EXPECT_FALSE(in_range(0.0, 1.0, false)(1.0));
  EXPECT_FALSE(open_closed(0.0, 1.0)(0.0));
  EXPECT_TRUE(open_closed(0.0, 1.0)(1.0));
}

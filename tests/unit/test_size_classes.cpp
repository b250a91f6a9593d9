// The size-class neighbour search (crush_size_classes.h) against the brute-force pair set: every
// pair within (r_i + r_j) cdf + skin found exactly once, as bin style stores it, for any bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "crush_size_classes.h"

using namespace crush;

namespace {

struct Cloud {
  std::vector<std::vector<double>> position;
  std::vector<double> radius;
  std::vector<const double *> rows;

  const double *const *x() {
    rows.clear();
    for (const auto &p : position) rows.push_back(p.data());
    return rows.data();
  }
};

// Spheres of radii from r_small to 8 r_small (most of them small, as after crushing) in a box;
// the first 'iterated' are the rank's own, the others stand for ghosts and may lie anywhere.
Cloud polydisperse_cloud(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> where(0.0, 1.0e-2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Cloud c;
  for (int i = 0; i < n; ++i) {
    c.position.push_back({where(gen), where(gen), where(gen)});
    c.radius.push_back(1.0e-4 * std::pow(8.0, unit(gen) * unit(gen)));
  }
  return c;
}

using Pairs = std::set<std::pair<int, int>>;

// Bin style's set: each owned/owned pair once, each owned/ghost pair once, within the cutoff.
Pairs brute_force(const Cloud &c, int iterated, double cdf, double skin) {
  Pairs pairs;
  const int n = static_cast<int>(c.radius.size());
  for (int i = 0; i < iterated; ++i)
    for (int j = i + 1; j < n; ++j) {
      double rsq = 0.0;
      for (int d = 0; d < 3; ++d) rsq += std::pow(c.position[i][d] - c.position[j][d], 2);
      const double cut = (c.radius[i] + c.radius[j]) * cdf + skin;
      if (rsq <= cut * cut) pairs.insert({i, j});
    }
  return pairs;
}

// The classes' set; fails on a pair stored twice or a distance given wrong.
Pairs by_classes(Cloud &c, int iterated, const SizeClassBounds &bounds, double cdf, double skin) {
  SizeClassBins bins;
  const int n = static_cast<int>(c.radius.size());
  bins.build(bounds, c.x(), c.radius.data(), n, cdf, skin);
  bins.collect_reverse(iterated);
  Pairs pairs;
  for (int i = 0; i < iterated; ++i)
    bins.for_each_neighbor(i, [&](int j, double rsq) {
      double expected = 0.0;
      for (int d = 0; d < 3; ++d) expected += std::pow(c.position[i][d] - c.position[j][d], 2);
      EXPECT_NEAR(rsq, expected, 1e-12 * expected);
      const std::pair<int, int> p = {std::min(i, j), std::max(i, j)};
      EXPECT_TRUE(pairs.insert(p).second) << "pair " << p.first << " " << p.second << " stored twice";
    });
  return pairs;
}


}  // namespace

TEST(SizeClasses, AutomaticBoundsAreAFactorTwoApartFromTheLargest) {
  SizeClassBounds bounds;
  const std::vector<double> b = bounds.bounds_for(1.0e-4, 8.0e-4);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_DOUBLE_EQ(b[0], 1.0e-4);
  EXPECT_DOUBLE_EQ(b[1], 2.0e-4);
  EXPECT_DOUBLE_EQ(b[2], 4.0e-4);
  EXPECT_TRUE(bounds.bounds_for(1.0e-4, 1.0e-4).empty());  // one size, one class
  EXPECT_EQ(bounds.bounds_for(1.0e-6, 1.0).size(), SizeClassBounds::kMaxAutoClasses - 1u);
}

TEST(SizeClasses, UserBoundsMustBePositiveAndIncreasing) {
  SizeClassBounds bounds;
  EXPECT_EQ(bounds.set_upper({2.0e-4, 4.0e-4}), "");
  EXPECT_FALSE(bounds.automatic());
  EXPECT_NE(bounds.set_upper({4.0e-4, 2.0e-4}), "");
  EXPECT_NE(bounds.set_upper({-1.0}), "");
  EXPECT_NE(bounds.set_upper({}), "");
}

TEST(SizeClasses, FindsBinStylesPairsOnOneRank) {
  Cloud c = polydisperse_cloud(3000, 7);
  const int n = static_cast<int>(c.radius.size());
  const Pairs expected = brute_force(c, n, 1.0, 5.0e-5);
  ASSERT_GT(expected.size(), 1000u);
  SizeClassBounds automatic;
  EXPECT_EQ(by_classes(c, n, automatic, 1.0, 5.0e-5), expected);
}

TEST(SizeClasses, FindsOwnedGhostPairsFromBothSides) {
  // the last third stands for ghosts: the pairs with them must be found whichever sphere is smaller
  Cloud c = polydisperse_cloud(3000, 11);
  const int iterated = 2000;
  const Pairs expected = brute_force(c, iterated, 1.0, 5.0e-5);
  SizeClassBounds automatic;
  EXPECT_EQ(by_classes(c, iterated, automatic, 1.0, 5.0e-5), expected);
}

TEST(SizeClasses, AnyBoundsAndAContactFactorGiveTheSamePairs) {
  Cloud c = polydisperse_cloud(2000, 3);
  const Pairs expected = brute_force(c, 1500, 1.5, 2.0e-5);
  for (const std::vector<double> &upper :
       {std::vector<double>{1.5e-4}, std::vector<double>{1.0e-4, 3.0e-4, 6.0e-4}, std::vector<double>{1.0e-3}}) {
    SizeClassBounds bounds;
    ASSERT_EQ(bounds.set_upper(upper), "");
    EXPECT_EQ(by_classes(c, 1500, bounds, 1.5, 2.0e-5), expected);
  }
}

TEST(SizeClasses, AFlatLayerAndASingleSphere) {
  // spheres on one plane (a box of zero height) and a lone sphere (no pair) still bin
  Cloud c = polydisperse_cloud(1500, 13);
  for (auto &p : c.position) p[2] = 5.0e-3;
  const Pairs expected = brute_force(c, 1500, 1.0, 5.0e-5);
  SizeClassBounds automatic;
  EXPECT_EQ(by_classes(c, 1500, automatic, 1.0, 5.0e-5), expected);
  Cloud one = polydisperse_cloud(1, 17);
  EXPECT_TRUE(by_classes(one, 1, automatic, 1.0, 5.0e-5).empty());
}

TEST(SizeClasses, LargeSpheresNeverSearchTheSmallClassesAmongOwnedOnes) {
  // on one rank a sphere of the largest class holds no pair with the smaller classes
  Cloud c = polydisperse_cloud(2000, 9);
  SizeClassBins bins;
  SizeClassBounds automatic;
  bins.build(automatic, c.x(), c.radius.data(), 2000, 1.0, 5.0e-5);
  bins.collect_reverse(2000);
  const int top = bins.classes() - 1;
  ASSERT_GE(top, 2);
  for (int i = 0; i < 2000; ++i) {
    if (bins.class_of(i) != top) continue;
    bins.for_each_neighbor(i, [&](int j, double) { EXPECT_EQ(bins.class_of(j), top); });
  }
}

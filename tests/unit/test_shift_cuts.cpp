// The shift balancer's cuts (crush_shift_cuts.h): equal counts per slab, one hop at most, no slab
// thinner than asked, and the imbalance factor.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "crush_model_error.h"
#include "crush_shift_cuts.h"

namespace {
// Counts below each cut of particles at the given fractions of the box (one processor).
crush::CountBelow counter(const std::vector<double> &positions)
{
  return [positions](const std::vector<double> &cuts) {
    std::vector<double> n(cuts.size(), 0.0);
    for (std::size_t k = 0; k < cuts.size(); k++)
      n[k] = static_cast<double>(std::count_if(positions.begin(), positions.end(),
                                               [&](double x) { return x < cuts[k]; }));
    return n;
  };
}

std::vector<double> counts(const std::vector<double> &positions, const std::vector<double> &cuts)
{
  std::vector<double> n(cuts.size() - 1, 0.0);
  for (double x : positions)
    for (std::size_t k = 0; k + 1 < cuts.size(); k++)
      if (x >= cuts[k] && x < cuts[k + 1]) n[k] += 1.0;
  return n;
}
}  // namespace

TEST(ShiftCuts, TwoSlabsSplitACrowdedCornerEvenly)
{
  // 600 particles crowd the first tenth of the box (fragments near an axis), 400 spread over the rest
  std::vector<double> x;
  for (int i = 0; i < 600; i++) x.push_back(0.1 * (i + 0.5) / 600);
  for (int i = 0; i < 400; i++) x.push_back(0.1 + 0.9 * (i + 0.5) / 400);
  const std::vector<double> cuts = crush::shift_cuts({0.0, 0.5, 1.0}, 1000, 30, 0.0, counter(x));
  EXPECT_NEAR(cuts[1], 0.1 * 500.0 / 600.0, 1e-3);  // half of the particles below
  EXPECT_EQ(counts(x, cuts), (std::vector<double>{500, 500}));
  EXPECT_DOUBLE_EQ(crush::imbalance(counts(x, {0.0, 0.5, 1.0})), 2.0 * 778.0 / 1000.0);  // 600 + 178 below 0.5
  EXPECT_DOUBLE_EQ(crush::imbalance(counts(x, cuts)), 1.0);
}

TEST(ShiftCuts, ACutMovesAtMostToItsNeighboursOldPlaces)
{
  // all particles in the last slab of four: one call moves each cut one slab at most, and repeated
  // calls approach equal counts
  std::vector<double> x;
  for (int i = 0; i < 400; i++) x.push_back(0.75 + 0.25 * (i + 0.5) / 400);
  std::vector<double> cuts = {0.0, 0.25, 0.5, 0.75, 1.0};
  const std::vector<double> once = crush::shift_cuts(cuts, 400, 30, 0.0, counter(x));
  for (int k = 1; k < 4; k++) {
    EXPECT_GE(once[k], cuts[k - 1]);
    EXPECT_LE(once[k], cuts[k + 1]);
  }
  for (int call = 0; call < 20; call++) cuts = crush::shift_cuts(cuts, 400, 30, 0.0, counter(x));
  EXPECT_LT(crush::imbalance(counts(x, cuts)), 1.02);
}

TEST(ShiftCuts, KeepsTheSmallestWidthAndRefusesBadInput)
{
  // every particle at one place: the cuts gather there but keep slabs of 0.05
  const std::vector<double> x(100, 0.3);
  const std::vector<double> cuts = crush::shift_cuts({0.0, 1.0 / 3, 2.0 / 3, 1.0}, 100, 30, 0.05, counter(x));
  for (int k = 0; k < 3; k++) EXPECT_GE(cuts[k + 1] - cuts[k], 0.05 - 1e-12);
  EXPECT_THROW(crush::shift_cuts({0.0, 0.6, 0.4, 1.0}, 100, 30, 0.0, counter(x)), crush::ModelError);
  EXPECT_THROW(crush::shift_cuts({0.0, 0.5, 1.0}, 100, 0, 0.0, counter(x)), crush::ModelError);
  EXPECT_THROW(crush::shift_cuts({0.0, 0.5, 1.0}, 100, 10, 0.5, counter(x)), crush::ModelError);
  EXPECT_DOUBLE_EQ(crush::imbalance({0, 0}), 1.0);
}

// Incremental shear force of mindlin/scaled: rotation into the tangent plane, the increment, the
// Coulomb cap, and the zero vector.
#include <gtest/gtest.h>

#include <cmath>

#include "hertz_mindlin_shear_law.h"

using namespace crush;

namespace {
double norm(const double *v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
}  // namespace

TEST(ShearLaw, RotationKeepsMagnitudeAndLeavesTheNormal)
{
  // The contact normal turned by 30 degrees about y: the stored force (3 N along x, 4 N along y) loses
  // its new normal component and keeps its 5 N.
  const double angle = M_PI / 6.0;
  const double en[3] = {std::sin(angle), 0.0, std::cos(angle)};
  double Fs[3] = {3.0, 4.0, 0.0};
  rotate_into_tangent_plane(Fs, en);
  EXPECT_NEAR(dot(Fs, en), 0.0, 1e-14);
  EXPECT_NEAR(norm(Fs), 5.0, 1e-14);
  // By hand: Fs - (Fs.en) en = (3 - 1.5 sin, 4, -1.5 cos) with Fs.en = 1.5, then scaled to 5 N.
  const double t[3] = {3.0 - 1.5 * std::sin(angle), 4.0, -1.5 * std::cos(angle)};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(Fs[k], t[k] * 5.0 / norm(t), 1e-14);
  // Already tangent: unchanged.
  const double ez[3] = {0.0, 0.0, 1.0};
  double tangent[3] = {1.0, -2.0, 0.0};
  rotate_into_tangent_plane(tangent, ez);
  EXPECT_EQ(tangent[0], 1.0);
  EXPECT_EQ(tangent[1], -2.0);
  EXPECT_EQ(tangent[2], 0.0);
}

TEST(ShearLaw, SmallTurnsKeepTheMagnitudeToRounding)
{
  // Turns of the contact plane from 1e-9 rad (a step of a quasi-static run) to 1e-2 rad: the rotated
  // force stays tangent, keeps its magnitude to a few ulp and agrees with the projection scaled by
  // the ratio of the magnitudes, computed here from the norms, to 1e-15 relative.
  for (double angle : {1e-9, 1e-6, 3e-4, 9e-4, 1e-3, 1e-2}) {
    const double en[3] = {std::sin(angle) * 0.6, std::sin(angle) * 0.8, std::cos(angle)};
    double Fs[3] = {-2.5e-3, 7.1e-3, 0.0};
    const double magnitude = norm(Fs);
    double exact[3] = {Fs[0], Fs[1], Fs[2]};
    const double d = dot(exact, en);
    for (int k = 0; k < 3; ++k) exact[k] -= d * en[k];
    const double scale = magnitude / norm(exact);
    for (int k = 0; k < 3; ++k) exact[k] *= scale;
    rotate_into_tangent_plane(Fs, en);
    EXPECT_NEAR(norm(Fs) / magnitude, 1.0, 4e-16) << "turn " << angle;
    EXPECT_NEAR(dot(Fs, en) / magnitude, 0.0, 1e-16) << "turn " << angle;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(Fs[k], exact[k], 1e-15 * magnitude) << "turn " << angle;
  }
}

TEST(ShearLaw, ZeroAndNormalVectors)
{
  const double ez[3] = {0.0, 0.0, 1.0};
  double zero[3] = {0.0, 0.0, 0.0};
  rotate_into_tangent_plane(zero, ez);
  EXPECT_EQ(norm(zero), 0.0);
  EXPECT_FALSE(cap_at_coulomb(zero, 0.0));  // no force, no friction: not sliding, no NaN
  EXPECT_EQ(norm(zero), 0.0);
  // A force along the new normal has no tangent part left: it vanishes instead of blowing up.
  double along[3] = {0.0, 0.0, 2.0};
  rotate_into_tangent_plane(along, ez);
  EXPECT_EQ(norm(along), 0.0);
  // A zero limit (no normal force) with a shear force: capped to zero.
  double f[3] = {1.0, 0.0, 0.0};
  EXPECT_TRUE(cap_at_coulomb(f, 0.0));
  EXPECT_EQ(norm(f), 0.0);
}

TEST(ShearLaw, IncrementIsMinusStiffnessTimesDisplacement)
{
  const double ez[3] = {0.0, 0.0, 1.0};
  // k_S = 2e5 N/m, dt = 1e-7 s, v_t = (0.3, -0.1, 0) m/s: du = (3e-8, -1e-8, 0) m, dF = -k du.
  double Fs[3] = {0.01, 0.0, 0.0};
  const double vt[3] = {0.3, -0.1, 0.0};
  increment_shear_force(Fs, ez, 2e5 * 1e-7, vt);
  EXPECT_NEAR(Fs[0], 0.01 - 2e5 * 3e-8, 1e-16);
  EXPECT_NEAR(Fs[1], 2e5 * 1e-8, 1e-16);
  EXPECT_EQ(Fs[2], 0.0);
}

TEST(ShearLaw, CoulombCapSlidesOnTheLimitKeepingDirection)
{
  // |Fs| = 5 N against mu |F_n| = 0.5 x 4 N = 2 N: scaled to 2 N along (0.6, 0.8, 0).
  double Fs[3] = {3.0, 4.0, 0.0};
  EXPECT_TRUE(cap_at_coulomb(Fs, 0.5 * 4.0));
  EXPECT_NEAR(Fs[0], 1.2, 1e-15);
  EXPECT_NEAR(Fs[1], 1.6, 1e-15);
  EXPECT_EQ(Fs[2], 0.0);
  // Below the limit (and exactly on it): sticking, untouched.
  double stick[3] = {1.2, 1.6, 0.0};
  EXPECT_FALSE(cap_at_coulomb(stick, 2.5));
  EXPECT_EQ(stick[0], 1.2);
  double on[3] = {3.0, 4.0, 0.0};
  EXPECT_FALSE(cap_at_coulomb(on, 5.0));
  EXPECT_EQ(on[1], 4.0);
}

// Fragment layouts: containment, tangencies, volume, centre of mass, rotations.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "crush_constants.h"
#include "crush_fragment_density.h"
#include "crush_fragments.h"
#include "hertz_mindlin_scaled_law.h"
#include "crush_model_error.h"

using namespace crush;

namespace {
const double tol = 1e-12;

// Checks containment, non-overlap, and counts tangencies (to the mother and between fragments).
void check_geometry(const std::vector<Fragment> &f, double R, int *mother_tangent, int *pair_tangent)
{
  *mother_tangent = *pair_tangent = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double reach = f[i].offset.norm() + f[i].radius;
    EXPECT_LE(reach, R * (1 + tol)) << "fragment " << i << " leaves the mother";
    if (std::fabs(reach - R) < tol * R) ++*mother_tangent;
    for (std::size_t j = i + 1; j < f.size(); ++j) {
      const double gap = (f[i].offset - f[j].offset).norm() - f[i].radius - f[j].radius;
      EXPECT_GE(gap, -tol * R) << "fragments " << i << " and " << j << " overlap";
      if (std::fabs(gap) < tol * R) ++*pair_tangent;
    }
  }
}

double volume_fraction(const std::vector<Fragment> &f, double R)
{
  double v = 0.0;
  for (const Fragment &x : f) v += std::pow(x.radius / R, 3);
  return v;
}
}  // namespace

TEST(Fragments, FourteenBallLayoutMatchesTheDesign)
{
  const double R = 1.7e-4;
  const auto f = fragment_layout(FragmentLayout::fourteen, R);
  ASSERT_EQ(f.size(), 14u);
  EXPECT_NEAR(f[0].radius / R, std::sqrt(2.0) - 1.0, tol);
  EXPECT_NEAR(f[0].offset.norm() / R, 2.0 - std::sqrt(2.0), tol);
  EXPECT_NEAR(f[13].radius / R, 0.230093, 1e-6);
  EXPECT_NEAR(f[13].offset.norm() / R, 0.769907, 1e-6);
  int mother = 0, pairs = 0;
  check_geometry(f, R, &mother, &pairs);
  EXPECT_EQ(mother, 14);  // every fragment touches the mother
  EXPECT_EQ(pairs, 12 + 24);  // 12 large-large edges of the octahedron, 3 large per small
  EXPECT_NEAR(volume_fraction(f, R), 0.523861, 1e-6);
  EXPECT_NEAR(kept_volume_fraction(FragmentLayout::fourteen), volume_fraction(f, R), tol);
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  for (const Fragment &x : f) com += std::pow(x.radius, 3) * x.offset;
  EXPECT_LT(com.norm() / std::pow(R, 4), tol);
  EXPECT_NEAR(smallest_fragment_ratio(FragmentLayout::fourteen), f[13].radius / R, tol);
}

TEST(Fragments, TetrahedralLayout)
{
  const auto f = fragment_layout(FragmentLayout::tetrahedral, 1.0);
  ASSERT_EQ(f.size(), 4u);
  int mother = 0, pairs = 0;
  check_geometry(f, 1.0, &mother, &pairs);
  EXPECT_EQ(mother, 4);
  EXPECT_EQ(pairs, 6);
  EXPECT_NEAR(kept_volume_fraction(FragmentLayout::tetrahedral), 4.0 * std::pow(0.4494897, 3), 1e-6);
}

TEST(Fragments, PropertiesHoldAfterRotation)
{
  const double R = 2.0e-4;
  const auto base = fragment_layout(FragmentLayout::fourteen, R);
  for (std::uint64_t tag = 1; tag < 50; ++tag) {
    const Eigen::Matrix3d rot = random_rotation(99, tag);
    EXPECT_NEAR((rot * rot.transpose() - Eigen::Matrix3d::Identity()).norm(), 0.0, tol);
    EXPECT_NEAR(rot.determinant(), 1.0, tol);
    const auto f = rotated(base, rot);
    int mother = 0, pairs = 0;
    check_geometry(f, R, &mother, &pairs);
    EXPECT_EQ(mother, 14);
    EXPECT_EQ(pairs, 36);
    Eigen::Vector3d com = Eigen::Vector3d::Zero();
    for (const Fragment &x : f) com += std::pow(x.radius, 3) * x.offset;
    EXPECT_LT(com.norm() / std::pow(R, 4), tol);
  }
  EXPECT_EQ(random_rotation(99, 5), random_rotation(99, 5));  // a function of (seed, tag)
  EXPECT_NE(random_rotation(99, 5), random_rotation(99, 6));
}

TEST(Fragments, RandomRotationsAreUniformOverSO3)
{
  // For a uniform rotation the image of a fixed axis is uniform on the sphere: its z component is
  // uniform on [-1, 1], and the rotation angle theta has density (1 - cos theta)/pi.
  const int n = 10000, bins = 10;
  std::vector<int> z_count(bins, 0), angle_count(bins, 0);
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix3d rot = random_rotation(2014, i + 1);
    const double z = (rot * Eigen::Vector3d::UnitX()).z();
    ++z_count[std::min(bins - 1, static_cast<int>((z + 1.0) / 2.0 * bins))];
    const double theta = std::acos(std::max(-1.0, std::min(1.0, (rot.trace() - 1.0) / 2.0)));
    // CDF of theta: (theta - sin theta)/pi; map to [0,1) so the bins are equally likely.
    const double u = (theta - std::sin(theta)) / pi;
    ++angle_count[std::min(bins - 1, static_cast<int>(u * bins))];
  }
  auto chi2 = [&](const std::vector<int> &c) {
    double x = 0.0;
    for (int k : c) x += (k - n / bins) * double(k - n / bins) / (n / bins);
    return x;
  };
  EXPECT_LT(chi2(z_count), 27.88);  // chi^2, 9 degrees of freedom, p = 0.001
  EXPECT_LT(chi2(angle_count), 27.88);
}

TEST(Fragments, InvalidRadius)
{
  EXPECT_THROW(fragment_layout(FragmentLayout::fourteen, 0.0), ModelError);
}

// fragment_density scaled: rho (R/r)^2 keeps r sqrt(rho), so the Rayleigh time, over generations.
TEST(FragmentDensity, ScaledKeepsTheGrainsRayleighTimeOverGenerations)
{
  const double R0 = 1e-3, rho0 = 2650.0;
  const crush::ShearMaterial quartz = crush::shear_material(7e10, 0.3);
  const double grain_time = crush::rayleigh_time_step(R0, rho0, quartz);
  double R = R0, rho = rho0;
  for (int generation = 1; generation <= 3; generation++) {
    const std::vector<crush::Fragment> fragments = crush::fragment_layout(crush::FragmentLayout::fourteen, R);
    double mass = 0.0;
    for (const crush::Fragment &f : fragments) {
      const double rho_f = crush::fragment_density(crush::FragmentDensity::scaled, rho, R, f.radius);
      EXPECT_NEAR(crush::rayleigh_time_step(f.radius, rho_f, quartz), grain_time, 1e-12 * grain_time);
      mass += rho_f * std::pow(f.radius, 3);
    }
    // The fragments weigh 6 (sqrt2 - 1) + 8 r2/R = 4.326 times their mother.
    EXPECT_NEAR(mass / (rho * std::pow(R, 3)), 6.0 * (std::sqrt(2.0) - 1.0) + 8.0 * 0.2300932, 1e-6);
    // The next generation breaks a small fragment.
    rho = crush::fragment_density(crush::FragmentDensity::scaled, rho, R, fragments.back().radius);
    R = fragments.back().radius;
  }
  // 'true': the mother's density, whatever the size.
  EXPECT_EQ(crush::fragment_density(crush::FragmentDensity::true_density, rho0, R0, 0.1 * R0), rho0);
}

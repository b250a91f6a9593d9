/* Crushing model (plain C++): fragment layouts (see crush_fragments.h). */
#include "crush_fragments.h"

#include <algorithm>
#include <cmath>

#include "crush_constants.h"
#include "crush_model_error.h"
#include "crush_random.h"

namespace crush {

namespace {

// Unit-radius geometry of the 14-sphere layout, derived from the tangency conditions.
struct FourteenGeometry {
  double a, r1, b, r2;
};

FourteenGeometry fourteen_geometry()
{
  const double sqrt2 = std::sqrt(2.0), sqrt3 = std::sqrt(3.0);
  FourteenGeometry g;
  g.a = 2.0 - sqrt2;        // from a + r1 = 1 and a sqrt2 = 2 r1
  g.r1 = 1.0 - g.a;
  const double s = 1.0 + g.r1;
  g.b = (s * s - g.a * g.a) / (2.0 * s - 2.0 * g.a / sqrt3);
  g.r2 = 1.0 - g.b;
  return g;
}

double tetrahedral_radius()
{
  // Centres at distance c = 1 - r on tetrahedron vertices; neighbours' distance c sqrt(8/3) = 2 r.
  return 1.0 / (1.0 + std::sqrt(1.5));
}

}  // namespace

std::vector<Fragment> fragment_layout(FragmentLayout layout, double mother_radius)
{
  require(mother_radius > 0.0, "mother radius", mother_radius, "> 0 m");
  const double R = mother_radius;
  std::vector<Fragment> out;
  if (layout == FragmentLayout::fourteen) {
    const FourteenGeometry g = fourteen_geometry();
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0}) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        c[axis] = sign * g.a * R;
        out.push_back({c, g.r1 * R});
      }
    const double diag = g.b * R / std::sqrt(3.0);
    for (double sx : {1.0, -1.0})
      for (double sy : {1.0, -1.0})
        for (double sz : {1.0, -1.0}) out.push_back({Eigen::Vector3d(sx, sy, sz) * diag, g.r2 * R});
  } else {
    const double r = tetrahedral_radius();
    const double c = (1.0 - r) * R / std::sqrt(3.0);
    for (const Eigen::Vector3d &v : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, -1, -1),
                                    Eigen::Vector3d(-1, 1, -1), Eigen::Vector3d(-1, -1, 1)})
      out.push_back({v * c, r * R});
  }
  return out;
}

double kept_volume_fraction(FragmentLayout layout)
{
  double kept = 0.0;
  for (const Fragment &f : fragment_layout(layout, 1.0)) kept += f.radius * f.radius * f.radius;
  return kept;
}

double smallest_fragment_ratio(FragmentLayout layout)
{
  double smallest = 1.0;
  for (const Fragment &f : fragment_layout(layout, 1.0)) smallest = std::min(smallest, f.radius);
  return smallest;
}

Eigen::Matrix3d random_rotation(std::uint64_t seed, std::uint64_t mother_tag)
{
  // Shoemake (Graphics Gems III, 1992): a uniform unit quaternion from three uniforms.
  const double u1 = uniform_open(seed, mother_tag, Stream::orientation, 0);
  const double u2 = uniform_open(seed, mother_tag, Stream::orientation, 1);
  const double u3 = uniform_open(seed, mother_tag, Stream::orientation, 2);
  const double s1 = std::sqrt(1.0 - u1), s2 = std::sqrt(u1);
  const Eigen::Quaterniond q(s2 * std::cos(2 * pi * u3), s1 * std::sin(2 * pi * u2),
                             s1 * std::cos(2 * pi * u2), s2 * std::sin(2 * pi * u3));
  return q.normalized().toRotationMatrix();
}

std::vector<Fragment> rotated(const std::vector<Fragment> &fragments, const Eigen::Matrix3d &rotation)
{
  std::vector<Fragment> out = fragments;
  for (Fragment &f : out) f.offset = rotation * f.offset;
  return out;
}

}  // namespace crush

/* Crushing model (plain C++): the fragments that replace a broken sphere (Ciantia et al. 2014,
   sec. 2.2, Fig. 1b).

   The default layout has 14 inscribed, mutually tangent spheres in a mother of radius R:
   - six "large" spheres centred on the +-x, +-y, +-z axes at distance a, radius r1, each tangent to
     the mother (a + r1 = R) and to its four neighbours (a sqrt2 = 2 r1): a = (2 - sqrt2) R,
     r1 = (sqrt2 - 1) R;
   - eight "small" spheres on the cube diagonals at distance b, radius r2, each tangent to the mother
     (b + r2 = R) and to the three large spheres around its diagonal
     (|b/sqrt3 (1,1,1) - a (1,0,0)| = r1 + r2), which gives
       b = ((R + r1)^2 - a^2) / (2 (R + r1) - 2 a / sqrt3)   (b = 0.769907 R, r2 = 0.230093 R).
   They keep 52.386% of the mother's volume; the rest is "removed" and accounted as fines.
   An alternative layout, selectable for comparison, is the 4 equal tangent spheres on the vertices
   of a tetrahedron (radius R / (1 + sqrt(3/2)), 36.3% of the volume).
   Layouts are rotated per event, uniformly over SO(3) from (seed, mother tag) by default. */
#ifndef CRUSH_FRAGMENTS_H
#define CRUSH_FRAGMENTS_H

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace crush {

enum class FragmentLayout { fourteen, tetrahedral };

// One fragment: centre offset from the mother's centre (m) and radius (m).
struct Fragment {
  Eigen::Vector3d offset;
  double radius;
};

// The layout for a mother of radius R (m), in the mother's reference orientation.
std::vector<Fragment> fragment_layout(FragmentLayout layout, double mother_radius);
// Fraction of the mother's volume that the layout keeps.
double kept_volume_fraction(FragmentLayout layout);
// Ratio of the layout's smallest fragment radius to the mother's radius.
double smallest_fragment_ratio(FragmentLayout layout);

// A rotation uniformly distributed over SO(3), from (seed, mother tag) alone (Shoemake's method).
Eigen::Matrix3d random_rotation(std::uint64_t seed, std::uint64_t mother_tag);
// The layout rotated by the given rotation.
std::vector<Fragment> rotated(const std::vector<Fragment> &fragments, const Eigen::Matrix3d &rotation);

}  // namespace crush

#endif

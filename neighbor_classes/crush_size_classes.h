/* Granular neighbour search by size class (plain C++): what 'neighbor SKIN multi' does for granular
   pair styles (neigh_gran_multi.cpp is the LIGGGHTS adapter).

   Bin style bins every sphere by the largest one: bins of half the largest cutoff 2 R_max + skin,
   and a stencil that reaches it, so a fragment of radius r searches a ball of radius 2 R_max + skin
   for neighbours no farther than r + R_max + skin. Here the spheres are split by radius into
   classes, each class binned on its own grid, and a sphere of class a searches the grid of class b
   only as far as cut_ab = (R_a + R_b) cdf + skin, R_a the largest radius present in class a and
   cdf the contact distance factor. A pair is stored once per rank, as bin style stores it:
     - same class: by the lower index (j > i);
     - different classes: by the smaller sphere, which searches the larger ones' grids;
     - unless the smaller sphere is not one the rank iterates (a ghost, or outside the include
       group): then the larger one takes it. Those pairs are found from the smaller sphere's side
       too, before the lists are built (a ghost searches the larger classes' grids, as an owned
       sphere would), so no large sphere ever searches a small class's fine grid.
   The classes are only a way to search: any bounds give the same pairs, and the largest radius of
   each class is measured from the spheres a rank holds at each build, so fragments created mid-run
   join their class and no bound can miss a pair. SI units (m). */
#ifndef CRUSH_SIZE_CLASSES_H
#define CRUSH_SIZE_CLASSES_H

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace crush {

// The class bounds of 'neigh_modify size_classes': automatic (a factor of 2 in radius between
// classes, from the largest radius present down to the smallest, at most kMaxAutoClasses) or the
// user's increasing upper radii, with the radii above the last bound in a class of their own.
class SizeClassBounds {
 public:
  static constexpr int kMaxAutoClasses = 6;
  static constexpr double kAutoRatio = 2.0;

  void set_auto() { upper_.clear(); automatic_ = true; }
  // Returns an empty string when the bounds are valid, else what is wrong with them.
  std::string set_upper(const std::vector<double> &upper);
  bool automatic() const { return automatic_; }

  // The upper bounds to use for spheres whose radii span [rmin, rmax].
  std::vector<double> bounds_for(double rmin, double rmax) const;

 private:
  bool automatic_ = true;
  std::vector<double> upper_;
};

// One class's bins over the box [lo, hi): positions outside (round-off at the upper faces) are
// clamped to the edge bins, which keeps every pair findable (clamping onto a box never lengthens a
// distance).
struct BinGrid {
  double lo[3] = {0, 0, 0};
  double size[3] = {1, 1, 1};
  double inv[3] = {1, 1, 1};
  int n[3] = {1, 1, 1};

  // Bins near 'target' wide (m), at least one per dimension.
  void setup(const double box_lo[3], const double box_hi[3], double target);
  int bins() const { return n[0] * n[1] * n[2]; }
  int coord(double x, int d) const {
    const int k = static_cast<int>(std::floor((x - lo[d]) * inv[d]));
    return std::min(std::max(k, 0), n[d] - 1);
  }
  int index(int ix, int iy, int iz) const { return (iz * n[1] + iy) * n[0] + ix; }
};

// The bins of one grid that hold every point within 'cut' of a point in bin (0,0,0): for each row
// (dy, dz) the half-width in x, or -1 where the row lies beyond the cut.
struct BinStencil {
  int sy = 0, sz = 0;
  std::vector<int> reach;  // (2 sz + 1) x (2 sy + 1), row (dy, dz) at (dz + sz)(2 sy + 1) + dy + sy
  double cut = 0.0;

  void setup(const BinGrid &grid, double cut);
};

// The classes, grids and bins of one build. Each class keeps its spheres sorted by bin, with their
// positions and radii copied beside them: a row of bins is one contiguous stretch of memory.
class SizeClassBins {
 public:
  SizeClassBins() = default;

  // Assigns a class to each of the n spheres (the rank's owned and ghost ones) and bins them over
  // the box that bounds them; contact_factor and skin give each pair's cutoff (r_i + r_j) cdf + skin.
  void build(const SizeClassBounds &bounds, const double *const *x, const double *radius, int n,
             double contact_factor, double skin);

  int classes() const { return static_cast<int>(rmax_.size()); }
  int class_of(int i) const { return class_of_[i]; }

  // Finds, for each sphere i < iterated, its neighbours j >= iterated (ghosts, spheres outside the
  // include group) of smaller classes: the pairs only i's list can hold. Call after build().
  void collect_reverse(int iterated);

  // Calls visit(j, rsq) for every neighbour j of the sphere i (< iterated) that i's list holds, by
  // the rule of the file comment: rsq, the squared distance, is within ((r_i + r_j) cdf + skin)^2.
  template <class Visit>
  void for_each_neighbor(int i, Visit &&visit) const;

 private:
  // The members of one class, sorted by bin: bin k holds [start[k], start[k + 1]).
  struct Members {
    std::vector<int> start;
    std::vector<int> index;
    std::vector<double> x, y, z, radius;
  };

  const BinStencil &stencil(int a, int b) const { return stencils_[a * classes() + b]; }
  void sort_members(const double *const *x, const double *radius, int n);
  // visit(k, rsq) for each member k of class b within the pair cutoff of a sphere at (xi, ri).
  template <class Visit>
  void scan(int b, const BinStencil &s, const double *xi, double ri, Visit &&visit) const;

  double contact_factor_ = 1.0, skin_ = 0.0;
  std::vector<int> class_of_;
  std::vector<double> rmax_;
  std::vector<int> population_;
  std::vector<BinGrid> grids_;
  std::vector<BinStencil> stencils_;
  std::vector<Members> members_;
  std::vector<int> slot_;  // per sphere, its place among its class's members
  std::vector<int> reverse_first_;  // collect_reverse: i's pairs are [first[i], first[i + 1])
  std::vector<int> reverse_j_;
  std::vector<double> reverse_rsq_;
};

template <class Visit>
void SizeClassBins::scan(int b, const BinStencil &s, const double *xi, double ri, Visit &&visit) const {
  const BinGrid &g = grids_[b];
  const Members &m = members_[b];
  const int ix = g.coord(xi[0], 0), iy = g.coord(xi[1], 1), iz = g.coord(xi[2], 2);
  const int width = 2 * s.sy + 1;
  for (int dz = -s.sz; dz <= s.sz; ++dz) {
    const int z = iz + dz;
    if (z < 0 || z >= g.n[2]) continue;
    for (int dy = -s.sy; dy <= s.sy; ++dy) {
      const int y = iy + dy;
      const int reach = s.reach[(dz + s.sz) * width + dy + s.sy];
      if (y < 0 || y >= g.n[1] || reach < 0) continue;
      const int first = m.start[g.index(std::max(ix - reach, 0), y, z)];
      const int end = m.start[g.index(std::min(ix + reach, g.n[0] - 1), y, z) + 1];
      for (int k = first; k < end; ++k) {
        const double dx = xi[0] - m.x[k], dy_ = xi[1] - m.y[k], dz_ = xi[2] - m.z[k];
        const double rsq = dx * dx + dy_ * dy_ + dz_ * dz_;
        const double cut = (ri + m.radius[k]) * contact_factor_ + skin_;
        if (rsq <= cut * cut) visit(k, rsq);
      }
    }
  }
}

template <class Visit>
void SizeClassBins::for_each_neighbor(int i, Visit &&visit) const {
  const int a = class_of_[i];
  const Members &own = members_[a];
  const double xi[3] = {own.x[slot_[i]], own.y[slot_[i]], own.z[slot_[i]]};
  const double ri = own.radius[slot_[i]];
  scan(a, stencil(a, a), xi, ri, [&](int k, double rsq) {
    if (own.index[k] > i) visit(own.index[k], rsq);
  });
  for (int b = a + 1; b < classes(); ++b) {
    if (population_[b] == 0) continue;
    const Members &m = members_[b];
    scan(b, stencil(a, b), xi, ri, [&](int k, double rsq) { visit(m.index[k], rsq); });
  }
  for (int k = reverse_first_[i]; k < reverse_first_[i + 1]; ++k) visit(reverse_j_[k], reverse_rsq_[k]);
}

}  // namespace crush

#endif

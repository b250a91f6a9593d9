/* Granular neighbour search by size class (plain C++): bounds, grids, stencils and the binning of
   one build. */
#include "crush_size_classes.h"

#include <cstdlib>
#include <limits>
#include <utility>

namespace crush {

namespace {

// A class's bins are as wide as its own pair cutoff, and at most one per sphere it holds: a sphere
// then scans 3 x 3 rows of 3 bins in each class it searches. Finer bins (half the cutoff, as style
// bin) test fewer candidates but pay more in short rows: on the O-1 sample at 100 MPa (40,000
// particles, radii 32:1) a build took 29 ms with half-cutoff bins at up to 4 per sphere, 22 ms so.
constexpr double kBinsPerSphere = 1.0;
constexpr double kBinWidthPerCut = 1.0;

double pair_cut(double ra, double rb, double contact_factor, double skin) {
  return (ra + rb) * contact_factor + skin;
}

}  // namespace

std::string SizeClassBounds::set_upper(const std::vector<double> &upper) {
  if (upper.empty()) return "expected at least one bound";
  for (std::size_t k = 0; k < upper.size(); ++k) {
    if (!(upper[k] > 0.0) || !std::isfinite(upper[k])) return "expected positive radii as bounds";
    if (k > 0 && !(upper[k] > upper[k - 1])) return "expected the bounds in increasing order";
  }
  upper_ = upper;
  automatic_ = false;
  return "";
}

std::vector<double> SizeClassBounds::bounds_for(double rmin, double rmax) const {
  if (!automatic_) return upper_;
  std::vector<double> bounds;
  if (!(rmin > 0.0) || !(rmax > rmin)) return bounds;
  // classes a factor kAutoRatio apart, counted down from the largest radius
  const int classes = std::min(kMaxAutoClasses,
                               1 + static_cast<int>(std::floor(std::log(rmax / rmin) / std::log(kAutoRatio))));
  for (int k = classes - 1; k >= 1; --k) bounds.push_back(rmax / std::pow(kAutoRatio, k));
  return bounds;
}

void BinGrid::setup(const double box_lo[3], const double box_hi[3], double target) {
  for (int d = 0; d < 3; ++d) {
    const double extent = std::max(box_hi[d] - box_lo[d], std::numeric_limits<double>::min());
    const double bins = std::floor(extent / target);
    n[d] = static_cast<int>(std::min(std::max(bins, 1.0), 1.0e6));
    lo[d] = box_lo[d];
    size[d] = extent / n[d];
    inv[d] = 1.0 / size[d];
  }
}

void BinStencil::setup(const BinGrid &grid, double cut_ab) {
  cut = cut_ab;
  // bins at offset k lie at least (|k| - 1) bins away from a point in bin 0
  auto half_width = [](double length, double size) {
    return static_cast<int>(std::floor(length / size)) + 1;
  };
  sy = std::min(half_width(cut, grid.size[1]), grid.n[1] - 1);
  sz = std::min(half_width(cut, grid.size[2]), grid.n[2] - 1);
  const int width = 2 * sy + 1;
  reach.assign(static_cast<std::size_t>(width) * (2 * sz + 1), -1);
  for (int dz = -sz; dz <= sz; ++dz) {
    const double gap_z = std::max(std::abs(dz) - 1, 0) * grid.size[2];
    for (int dy = -sy; dy <= sy; ++dy) {
      const double gap_y = std::max(std::abs(dy) - 1, 0) * grid.size[1];
      const double left = cut * cut - gap_y * gap_y - gap_z * gap_z;
      if (left < 0.0) continue;
      reach[(dz + sz) * width + dy + sy] = std::min(half_width(std::sqrt(left), grid.size[0]), grid.n[0] - 1);
    }
  }
}

void SizeClassBins::build(const SizeClassBounds &bounds, const double *const *x, const double *radius,
                          int n, double contact_factor, double skin) {
  contact_factor_ = contact_factor;
  skin_ = skin;
  double rmin = std::numeric_limits<double>::max(), rmax = 0.0;
  for (int i = 0; i < n; ++i) {
    rmin = std::min(rmin, radius[i]);
    rmax = std::max(rmax, radius[i]);
  }
  const std::vector<double> upper = bounds.bounds_for(rmin, rmax);
  const int classes = static_cast<int>(upper.size()) + 1;

  class_of_.resize(n);
  rmax_.assign(classes, 0.0);
  population_.assign(classes, 0);
  for (int i = 0; i < n; ++i) {
    const int k = static_cast<int>(std::lower_bound(upper.begin(), upper.end(), radius[i]) - upper.begin());
    class_of_[i] = k;
    rmax_[k] = std::max(rmax_[k], radius[i]);
    ++population_[k];
  }

  // the box of the spheres themselves: a sparse class's bins are sized by the volume they fill
  double box_lo[3], box_hi[3];
  for (int d = 0; d < 3; ++d) {
    box_lo[d] = std::numeric_limits<double>::max();
    box_hi[d] = -std::numeric_limits<double>::max();
  }
  for (int i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) {
      box_lo[d] = std::min(box_lo[d], x[i][d]);
      box_hi[d] = std::max(box_hi[d], x[i][d]);
    }
  double volume = 1.0;
  for (int d = 0; d < 3; ++d) {
    if (n == 0) box_lo[d] = box_hi[d] = 0.0;
    box_hi[d] = std::max(box_hi[d], box_lo[d] + rmax);  // a flat layer still has a thickness
    volume *= box_hi[d] - box_lo[d];
  }
  grids_.resize(classes);
  for (int b = 0; b < classes; ++b) {
    const double own_cut = kBinWidthPerCut * pair_cut(rmax_[b], rmax_[b], contact_factor, skin);
    const double sparse = std::cbrt(volume / (kBinsPerSphere * std::max(population_[b], 1)));
    grids_[b].setup(box_lo, box_hi, std::max(own_cut, sparse));
  }

  stencils_.resize(static_cast<std::size_t>(classes) * classes);
  for (int a = 0; a < classes; ++a)
    for (int b = 0; b < classes; ++b)
      stencils_[a * classes + b].setup(grids_[b], pair_cut(rmax_[a], rmax_[b], contact_factor, skin));

  sort_members(x, radius, n);
}

void SizeClassBins::sort_members(const double *const *x, const double *radius, int n) {
  const int classes = this->classes();
  members_.resize(classes);
  std::vector<int> bin_of(n);
  for (int b = 0; b < classes; ++b) members_[b].start.assign(population_[b] ? grids_[b].bins() + 1 : 1, 0);
  for (int i = 0; i < n; ++i) {
    const BinGrid &g = grids_[class_of_[i]];
    bin_of[i] = g.index(g.coord(x[i][0], 0), g.coord(x[i][1], 1), g.coord(x[i][2], 2));
    ++members_[class_of_[i]].start[bin_of[i] + 1];
  }
  for (int b = 0; b < classes; ++b) {
    Members &m = members_[b];
    for (std::size_t k = 1; k < m.start.size(); ++k) m.start[k] += m.start[k - 1];
    m.index.resize(population_[b]);
    m.x.resize(population_[b]);
    m.y.resize(population_[b]);
    m.z.resize(population_[b]);
    m.radius.resize(population_[b]);
  }
  // by increasing index within each bin
  std::vector<std::vector<int>> fill(classes);
  for (int b = 0; b < classes; ++b) fill[b].assign(members_[b].start.begin(), members_[b].start.end() - 1);
  slot_.resize(n);
  for (int i = 0; i < n; ++i) {
    Members &m = members_[class_of_[i]];
    const int k = fill[class_of_[i]][bin_of[i]]++;
    slot_[i] = k;
    m.index[k] = i;
    m.x[k] = x[i][0];
    m.y[k] = x[i][1];
    m.z[k] = x[i][2];
    m.radius[k] = radius[i];
  }
}

void SizeClassBins::collect_reverse(int iterated) {
  const int n = static_cast<int>(class_of_.size());
  struct Found { int i, j; double rsq; };
  std::vector<Found> found;
  for (int j = iterated; j < n; ++j) {
    const int b = class_of_[j];
    const Members &own = members_[b];
    const double xj[3] = {own.x[slot_[j]], own.y[slot_[j]], own.z[slot_[j]]};
    for (int a = b + 1; a < classes(); ++a) {
      if (population_[a] == 0) continue;
      const Members &m = members_[a];
      scan(a, stencil(b, a), xj, own.radius[slot_[j]], [&](int k, double rsq) {
        if (m.index[k] < iterated) found.push_back({m.index[k], j, rsq});
      });
    }
  }
  reverse_first_.assign(iterated + 1, 0);
  for (const Found &f : found) ++reverse_first_[f.i + 1];
  for (int i = 0; i < iterated; ++i) reverse_first_[i + 1] += reverse_first_[i];
  reverse_j_.resize(found.size());
  reverse_rsq_.resize(found.size());
  std::vector<int> next(reverse_first_.begin(), reverse_first_.end() - 1);
  for (const Found &f : found) {
    const int k = next[f.i]++;
    reverse_j_[k] = f.j;
    reverse_rsq_[k] = f.rsq;
  }
}

}  // namespace crush

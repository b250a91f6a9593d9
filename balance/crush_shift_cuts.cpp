/* Load balance (plain C++): cut placement (see crush_shift_cuts.h). */
#include "crush_shift_cuts.h"

#include <algorithm>

#include "crush_model_error.h"

namespace crush {

std::vector<double> shift_cuts(const std::vector<double> &old_cuts, double total, int halvings,
                               double min_width, const CountBelow &below)
{
  const std::size_t slabs = old_cuts.size() - 1;
  if (old_cuts.size() < 2 || old_cuts.front() != 0.0 || old_cuts.back() != 1.0 ||
      !std::is_sorted(old_cuts.begin(), old_cuts.end()))
    throw ModelError("the old cuts must ascend from 0 to 1");
  if (halvings < 1) throw ModelError("at least one bisection step is needed");
  if (!(min_width >= 0.0 && min_width * static_cast<double>(slabs) < 1.0))
    throw ModelError("the slabs' smallest width must lie in [0, 1/P)");
  if (slabs < 2 || !(total > 0.0)) return old_cuts;
  // cut k lies in [old k-1, old k+1]: one hop for every particle
  std::vector<double> lo(old_cuts.begin(), old_cuts.end() - 2), hi(old_cuts.begin() + 2, old_cuts.end());
  std::vector<double> mid(slabs - 1);
  for (int step = 0; step < halvings; step++) {
    for (std::size_t k = 0; k + 1 < slabs; k++) mid[k] = 0.5 * (lo[k] + hi[k]);
    const std::vector<double> counts = below(mid);
    for (std::size_t k = 0; k + 1 < slabs; k++) {
      const double target = total * static_cast<double>(k + 1) / static_cast<double>(slabs);
      (counts[k] < target ? lo[k] : hi[k]) = mid[k];
    }
  }
  std::vector<double> cuts(old_cuts);
  // the upper end: the count below it reached the target, which the midpoint may miss by a particle
  for (std::size_t k = 0; k + 1 < slabs; k++) cuts[k + 1] = hi[k];
  // no slab thinner than min_width, also where two targets fall in one gap between particles
  for (std::size_t k = 1; k < slabs; k++) cuts[k] = std::max(cuts[k], cuts[k - 1] + min_width);
  for (std::size_t k = slabs - 1; k >= 1; k--) cuts[k] = std::min(cuts[k], cuts[k + 1] - min_width);
  return cuts;
}

double imbalance(const std::vector<double> &counts)
{
  double sum = 0.0, largest = 0.0;
  for (double c : counts) {
    sum += c;
    largest = std::max(largest, c);
  }
  return sum > 0.0 ? largest * static_cast<double>(counts.size()) / sum : 1.0;
}

}  // namespace crush

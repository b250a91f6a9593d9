/* Load balance (plain C++): where to put the cuts between the slabs of processors along one axis so
   that each slab holds the same number of particles (a shift balancer: the grid of processors stays,
   its planes move).

   Cuts are fractions of the box length: 0 = c_0 < c_1 < ... < c_{P-1} < c_P = 1 for P slabs. Cut k
   is placed by bisection where the count of particles below it reaches k/P of all, and stays between
   the old cuts k-1 and k+1: every particle then moves at most to a neighbouring slab, the one hop
   that LIGGGHTS' exchange of atoms and of mesh elements handles. Several calls converge to the
   balanced cuts when a hop is not enough. */
#ifndef CRUSH_SHIFT_CUTS_H
#define CRUSH_SHIFT_CUTS_H

#include <functional>
#include <vector>

namespace crush {

// below(cuts): for each candidate cut, the number of particles below it over all processors (one
// reduction for all cuts of a bisection step: the LIGGGHTS adapter sums over processors).
using CountBelow = std::function<std::vector<double>(const std::vector<double> &cuts)>;

// The P + 1 new cuts from the old ones (old_cuts.front() == 0, old_cuts.back() == 1, ascending),
// total the number of particles, after 'halvings' bisection steps per cut (resolution 2^-halvings
// of the span between the neighbouring old cuts). No slab is thinner than min_width (a fraction of
// the box, below 1/P: a slab as thin as the ghost cutoff still holds its contacts' partners).
std::vector<double> shift_cuts(const std::vector<double> &old_cuts, double total, int halvings,
                               double min_width, const CountBelow &below);

// Largest count over the mean: max(counts) / (sum(counts) / counts.size()); 1 when balanced, and
// when there is nothing to count.
double imbalance(const std::vector<double> &counts);

}  // namespace crush

#endif

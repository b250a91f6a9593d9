/* ----------------------------------------------------------------------
   liggghts-crush: the planes between processors, placed by the weight of the particles on each side
   (the LIGGGHTS side of crush_shift_cuts.h), shared by the balance command (between runs) and fix
   balance (within a run). See doc/balance.txt and doc/fix_balance.txt.

   Settings, as both take them: thresh shift dimstr niter stopthresh [weight neighbors]
     thresh: rebalance only if the fullest processor holds more than thresh times the mean weight
     dimstr: the axes whose cuts move (x, y, z in any order, each once); niter: bisection steps per
     cut; stopthresh: the axes after the one that brings the imbalance to stopthresh or below are left
     weight neighbors: each particle weighs 1 + its neighbours within r_i + r_j + skin (the pair
     loop's work), counted among its processor's particles and ghosts; else every particle weighs 1

   balance() moves comm->xsplit/ysplit/zsplit (uniform = 0) and nothing else: the caller moves the
   particles (the command at once, the fix through the step's exchange).
------------------------------------------------------------------------- */
#ifndef LMP_BALANCE_CUTS_H
#define LMP_BALANCE_CUTS_H

#include <string>
#include <vector>

#include "pointers.h"

namespace LAMMPS_NS {

class BalanceCuts : protected Pointers {
 public:
  // what one call did: the imbalance (largest weight over the mean) before and after, the axes moved
  struct Outcome {
    double before = 1.0, after = 1.0;
    std::string moved;
  };

  // who: the command's name in its errors ("balance", "fix balance (id bal)"); arg: the settings
  BalanceCuts(class LAMMPS *, const std::string &who, int narg, char **arg);

  // the imbalance of the current planes with the particles where they are now
  double imbalance();
  // moves the planes if the imbalance passes thresh, keeps them if the new ones are no better
  Outcome balance();
  // "imbalance a -> b (largest ... over the mean), x cuts ..." for the log
  std::string describe(const Outcome &) const;
  bool by_work() const { return by_work_; }

 private:
  double *split(int dim) const;
  void find_weights();
  void count_neighbours();
  std::vector<double> counts_below(int dim, const std::vector<double> &cuts) const;
  std::vector<double> counts_per_processor() const;
  void shift(int dim);
  void fail(const std::string &what) const;  // error->all, naming the command

  std::string who_;
  double thresh_ = 1.0, stop_ = 1.0;
  std::string axes_;
  int halvings_ = 20;
  bool by_work_ = false;
  std::vector<double> weight_;  // per local particle: 1, or 1 + its neighbour pairs (weight neighbors)
  double total_weight_ = 0.0;   // over all processors
};

}  // namespace LAMMPS_NS

#endif

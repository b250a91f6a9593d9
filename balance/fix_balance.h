/* ----------------------------------------------------------------------
   liggghts-crush: fix balance, the shift balancer of the balance command within a run (LIGGGHTS
   3.8.0 has neither). See doc/fix_balance.txt.

   fix ID group balance Nevery thresh shift dimstr niter stopthresh [weight neighbors] [out file]
     Nevery: check the balance every Nevery steps (a neighbour rebuild is forced on those steps)
     thresh ... weight neighbors: the balance command's settings (balance_cuts.h); the group is ignored
     out: a file with one line a move (step, imbalance before and after, the planes)

   On each checked step, before the step's exchange of particles: the planes between processors
   move if the fullest processor holds more than thresh times the mean weight, each at most to its
   neighbouring old planes, so that the step's own exchange (one hop) moves the particles and the
   meshes' elements; the contact histories and every fix's per-atom data travel with them. Output:
   scalar = the imbalance after the last check; vector = (imbalance before the last move, after it,
   moves so far, checks so far).
------------------------------------------------------------------------- */
#ifdef FIX_CLASS

FixStyle(balance,FixBalance)

#else

#ifndef LMP_FIX_BALANCE_H
#define LMP_FIX_BALANCE_H

#include <cstdio>
#include <memory>

#include "fix.h"

namespace LAMMPS_NS {

class BalanceCuts;

class FixBalance : public Fix {
 public:
  FixBalance(class LAMMPS *, int, char **);
  ~FixBalance();
  int setmask();
  void init();
  void setup_pre_exchange();
  void pre_exchange();
  double compute_scalar();
  double compute_vector(int);

 private:
  bool rebalance();  // whether the planes moved
  void schedule();  // the next checked step: the next multiple of every_

  std::unique_ptr<BalanceCuts> cuts_;
  int every_;
  double now_;             // imbalance after the last check
  double before_, after_;  // of the last move
  long moves_, checks_;
  FILE *out_;              // the moves (out keyword), on proc 0
};

}  // namespace LAMMPS_NS

#endif
#endif

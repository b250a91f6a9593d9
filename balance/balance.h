/* ----------------------------------------------------------------------
   liggghts-crush: balance, a shift balancer between runs (LIGGGHTS 3.8.0 has no balance command).
   See doc/balance.txt.

   balance thresh shift dimstr niter stopthresh [weight neighbors]
     thresh: rebalance only if the fullest processor holds more than thresh times the mean count
       (the mean work with 'weight neighbors': each particle weighs 1 + its neighbours within
       r_i + r_j + skin, the pair loop's work, counted among the particles and ghosts)
     dimstr: the axes whose cuts move (x, y, z in any order), each once, in that order
     niter: bisection steps per cut (resolution 2^-niter of its span)
     stopthresh: the axes after the one that brings the imbalance to stopthresh or below are left

   The processor grid stays; its planes move (balance_cuts.h: each slab holds as much weight as the
   others, each cut at most to its neighbouring old ones, the one hop of LIGGGHTS' exchange of atoms
   and of mesh elements). The atoms move to their new processors at once, also right after
   read_restart; the next run starts with a full setup (its 'pre no' too). fix balance does the same
   within a run.
------------------------------------------------------------------------- */
#ifdef COMMAND_CLASS

CommandStyle(balance,Balance)

#else

#ifndef LMP_BALANCE_H
#define LMP_BALANCE_H

#include <string>

#include "pointers.h"

namespace LAMMPS_NS {

class Balance : protected Pointers {
 public:
  Balance(class LAMMPS *);
  void command(int, char **);

 private:
  void migrate();
  void fail(const std::string &what) const;  // error->all, naming the command
};

}  // namespace LAMMPS_NS

#endif
#endif

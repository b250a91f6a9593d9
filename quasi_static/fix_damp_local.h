/* ----------------------------------------------------------------------
   liggghts-crush: fix damp/local, PFC's local damping (see local_damping_law.h).

   fix ID group damp/local alpha 0.05 [moments yes|no]

   Acts on the total force and moment of each particle, so it must come after every fix that adds
   forces in post_force (walls, gravity): init() checks the order.
------------------------------------------------------------------------- */
#ifdef FIX_CLASS

FixStyle(damp/local,FixDampLocal)

#else

#ifndef LMP_FIX_DAMP_LOCAL_H
#define LMP_FIX_DAMP_LOCAL_H

#include "fix.h"

namespace LAMMPS_NS {

class FixDampLocal : public Fix {
 public:
  FixDampLocal(class LAMMPS *, int, char **);
  int setmask();
  void init();
  void setup(int);
  void post_force(int);

  double alpha() const { return alpha_; }

 private:
  void check_order() const;

  double alpha_;
  bool damp_moments_;
};

}  // namespace LAMMPS_NS

#endif
#endif

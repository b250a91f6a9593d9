/* ----------------------------------------------------------------------
   liggghts-crush: fix dt/stiffness, PFC's automatic time step: the step follows the current
   Hertz-Mindlin contact stiffness (critical_step_law.h). See doc/fix_dt_stiffness.txt.

   fix ID group dt/stiffness fraction f [every M] [growth g] [max dt_max]

   Every M steps, after each reneighboring and while the step shrinks fast: dt = f x the smallest
   critical step of the group's particles, from their contacts with other particles (eq. 8-9 with
   the youngsModulus/poissonsRatio of the types) and with the walls of any fix wall/servo; dt grows
   by at most the factor g per update and never exceeds dt_max. The LIGGGHTS 'timestep' is the
   starting value. Output: scalar = current step (s).
------------------------------------------------------------------------- */
#ifdef FIX_CLASS

FixStyle(dt/stiffness,FixDtStiffness)

#else

#ifndef LMP_FIX_DT_STIFFNESS_H
#define LMP_FIX_DT_STIFFNESS_H

#include <cstdio>
#include <vector>

#include "contact_stiffness_monitor.h"
#include "critical_step_law.h"
#include "fix.h"

namespace LAMMPS_NS {

class FixDtStiffness : public Fix {
 public:
  FixDtStiffness(class LAMMPS *, int, char **);
  ~FixDtStiffness();
  int setmask();
  void init();
  void setup_pre_force(int);
  void setup(int);
  void pre_force(int);
  void end_of_step();
  double compute_scalar();
  void write_restart(FILE *);
  void restart(char *);

 private:
  void collect_stiffness(bool update_now);
  void update_time_step();
  void add_pair_contacts();
  void set_time_step(double dt);
  void warn_collapse(double local_radius);

  double fraction_, growth_, dt_max_;
  double dt_start_;  // the step after the first setup
  int every_;        // update interval (steps); reneighboring steps update too
  bool stiffening_;  // the last update shrank the step by more than growth_: update next step too
  bool warned_;
  bool updating_;    // this step updates the time step (decided at pre_force)
  bool published_;   // the contact model (hertz/scaled) fills stiffness_ during the force pass
  std::vector<crush::HertzMindlinCoefficients> coefficients_;  // per type pair, (ntypes+1)^2
  std::vector<crush::ContactStiffness> stiffness_;             // per local and ghost particle
  ContactStiffnessRecorder recorder_;
};

}  // namespace LAMMPS_NS

#endif
#endif

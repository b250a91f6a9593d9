/* ----------------------------------------------------------------------
   liggghts-crush: the link between the contact models and fix crush.

   A fix crush owns a CrushRecorder; the hertz/scaled normal model asks its CrushMonitor for it at
   each contact and, when one exists, records the contact's load on the particle and on its partner
   ball (F_n / F_lim of eq. 5/7/10 once divided by the strength term). Without a fix crush the
   per-contact cost is one integer compare: the monitor re-resolves its recorder only when a crush fix
   was created or deleted, or (with 'every' > 1) is attached for a checked step and detached for the
   others.
------------------------------------------------------------------------- */
#ifndef LMP_FIX_CRUSH_MONITOR_H
#define LMP_FIX_CRUSH_MONITOR_H

#include <cmath>

namespace LAMMPS_NS {

class LAMMPS;

// Records, per particle, the largest F_n (4 E'/3)^2 / r'^2 over its contacts during one force
// computation. Fix crush divides it by (pi sigma_lim)^3 afterwards, which gives the largest
// F_n / F_lim of eq. 5: the strength, a per-particle factor, stays out of the per-contact work.
class CrushRecorder {
 public:
  CrushRecorder() : load(0), inv_limit_factor(0) {}

  // inv_limit_factor[itype][jtype] = (4 E'/3)^2 (Pa^2); F_n the elastic normal force (N); r' the
  // contact's effective radius (m), r_i r_j/(r_i + r_j) (a plane: r_i), which the contact model has
  // at hand: reading per-particle radii here would add a scattered load per contact.
  inline void record(int i, int j, bool is_wall, int itype, int jtype, double normal_force,
                     double effective_radius) const
  {
    const double value = normal_force * inv_limit_factor[itype][jtype] / (effective_radius * effective_radius);
    // Branch-free maxima: the comparisons are unpredictable, a mispredicted branch costs more than
    // the store.
    load[i] = load[i] > value ? load[i] : value;
    // load has room for ghosts too: no test of j against nlocal (ghost entries are ignored)
    if (!is_wall) load[j] = load[j] > value ? load[j] : value;
  }

  double *load;              // per local and ghost atom (Pa^3); fix crush reads the local ones
  double **inv_limit_factor;
};

// Resolves the recorder of the crush fix of one LAMMPS instance, if any.
class CrushMonitor {
 public:
  explicit CrushMonitor(LAMMPS *lmp) : lmp_(lmp), generation_(-1), recorder_(0) {}

  inline const CrushRecorder *recorder()
  {
    if (generation_ != generation) resolve();
    return recorder_;
  }

  // Called by fix crush when it is created or starts a checked step (recorder), and when it is
  // deleted or starts an unchecked step with 'every' > 1 (NULL).
  static void attach(LAMMPS *lmp, const CrushRecorder *recorder);

  static int generation;  // changes whenever a recorder is attached or detached

 private:
  void resolve();
  LAMMPS *lmp_;
  int generation_;
  const CrushRecorder *recorder_;
};

}  // namespace LAMMPS_NS

#endif

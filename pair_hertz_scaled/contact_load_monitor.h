/* ----------------------------------------------------------------------
   liggghts-crush: how the contact models publish each contact's load (hertz_mindlin_contact_load.h).

   The contact layer owns this interface; a consumer (fix crush) owns a ContactLoadRecorder and
   attaches it. The hertz/scaled normal model and fix wall/servo ask their ContactLoadMonitor for it
   at each contact and, when one is attached, record the contact's load on the particle and on its
   partner ball (F_n / F_lim of eq. 5/7/10 once divided by the consumer's strength term). Without a
   recorder the per-contact cost is one integer compare: the monitor re-resolves only when a recorder
   was attached or detached (fix crush with 'every' > 1 attaches it for checked steps only).
------------------------------------------------------------------------- */
#ifndef LMP_CONTACT_LOAD_MONITOR_H
#define LMP_CONTACT_LOAD_MONITOR_H

#include <cmath>

#include "hertz_mindlin_contact_load.h"

namespace LAMMPS_NS {

class LAMMPS;

// Records, per particle, the largest contact load F_n (4 E'/3)^2 / r'^2 over its contacts during one
// force computation. Fix crush multiplies it by 1/(pi sigma_lim)^3 afterwards, which gives the
// largest F_n / F_lim of eq. 5: the strength, a per-particle factor, stays out of the per-contact work.
class ContactLoadRecorder {
 public:
  ContactLoadRecorder() : load(0), limit_factor(0) {}

  // limit_factor[itype][jtype] = (4 E'/3)^2 (Pa^2); F_n the elastic normal force (N); r' the
  // contact's effective radius (m), r_i r_j/(r_i + r_j) (a plane: r_i), which the contact model has
  // at hand: reading per-particle radii here would add a scattered load per contact.
  inline void record(int i, int j, bool is_wall, int itype, int jtype, double normal_force,
                     double effective_radius) const
  {
    const double value = crush::contact_load(normal_force, effective_radius, limit_factor[itype][jtype]);
    // Branch-free maxima: the comparisons are unpredictable, a mispredicted branch costs more than
    // the store.
    load[i] = load[i] > value ? load[i] : value;
    // load has room for ghosts too: no test of j against nlocal (ghost entries are ignored)
    if (!is_wall) load[j] = load[j] > value ? load[j] : value;
  }

  double *load;              // per local and ghost atom (Pa^3); fix crush reads the local ones
  double **limit_factor;
};

// Resolves the recorder of the crush fix of one LAMMPS instance, if any.
class ContactLoadMonitor {
 public:
  explicit ContactLoadMonitor(LAMMPS *lmp) : lmp_(lmp), generation_(-1), recorder_(0) {}

  inline const ContactLoadRecorder *recorder()
  {
    if (generation_ != generation) resolve();
    return recorder_;
  }

  // Called by fix crush when it is created or starts a checked step (recorder), and when it is
  // deleted or starts an unchecked step with 'every' > 1 (NULL).
  static void attach(LAMMPS *lmp, const ContactLoadRecorder *recorder);

  static int generation;  // changes whenever a recorder is attached or detached

 private:
  void resolve();
  LAMMPS *lmp_;
  int generation_;
  const ContactLoadRecorder *recorder_;
};

}  // namespace LAMMPS_NS

#endif

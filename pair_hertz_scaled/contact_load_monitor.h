/* ----------------------------------------------------------------------
   liggghts-crush: how the contact models publish each contact's load (hertz_mindlin_contact_load.h).

   Fix crush owns a ContactLoadRecorder and attaches it (contact_monitor.h). Every LIGGGHTS contact,
   whatever its models, is recorded by the granular pair loop and the wall contact once all models
   have run (patches/0009: the pair loop has an instance that records and one that does not), and
   fix wall/servo records its own walls: the load on the particle and on its partner ball (F_n / F_lim of
   eq. 5/7/10 once divided by the consumer's strength term). Fix crush with 'every' > 1 attaches it
   for checked steps only.
------------------------------------------------------------------------- */
#ifndef LMP_CONTACT_LOAD_MONITOR_H
#define LMP_CONTACT_LOAD_MONITOR_H

#include <cmath>

#include "contact_monitor.h"
#include "hertz_mindlin_contact_load.h"

namespace LAMMPS_NS {

// Records, per particle, the largest contact load F_n (4 E'/3)^2 / r'^2 over its contacts during one
// force computation. Fix crush multiplies it by 1/(pi sigma_lim)^3 afterwards, which gives the
// largest F_n / F_lim of eq. 5: the strength, a per-particle factor, stays out of the per-contact work.
class ContactLoadRecorder {
 public:
  ContactLoadRecorder() : load(0), limit_factor(0), total_force(false) {}

  // One contact as LIGGGHTS' contact models leave it (SurfacesIntersectData after all of them). The
  // elastic force is k_n U: the secant stiffness times the overlap, exact for hooke, hertz, their
  // /stiffness forms and hertz/scaled (fix crush refuses it for the plastic models, whose k_n U
  // overstates the unloading force); 'force total' reads F_n with viscous damping and with the
  // cohesion that LIGGGHTS' cohesion models add to it. r' from the radii (a wall: r_i).
  template <class ContactData>
  inline void record(const ContactData &c) const
  {
    const double effective_radius = c.is_wall ? c.radi : c.radi * c.radj / (c.radi + c.radj);
    record(c.i, c.j, c.is_wall, c.itype, c.jtype, total_force ? c.Fn : c.kn * c.deltan, effective_radius);
  }

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
  bool total_force;          // fix crush's 'force total': F_n with damping and cohesion, not k_n U
};

// The crush fix's recorder, if one is attached (contact_monitor.h).
typedef ContactMonitor<ContactLoadRecorder> ContactLoadMonitor;

}  // namespace LAMMPS_NS

#endif

/* ----------------------------------------------------------------------
   liggghts-crush: the contact stiffness the hertz/scaled model publishes for fix dt/stiffness.

   The normal model evaluates eq. 8-9 at every contact for the forces; when fix dt/stiffness is
   going to update the time step it attaches a ContactStiffnessRecorder (contact_monitor.h) before
   the force pass, and the model adds each particle-particle contact's k_n + k_s and k_s to both
   particles (hertz_mindlin_stiffness_sum.h): the fix then needs no walk of its own over the
   neighbour list. Same contacts, same overlaps, same order as such a walk: the same sums to the bit.
------------------------------------------------------------------------- */
#ifndef LMP_CONTACT_STIFFNESS_MONITOR_H
#define LMP_CONTACT_STIFFNESS_MONITOR_H

#include "contact_monitor.h"
#include "hertz_mindlin_stiffness_sum.h"

namespace LAMMPS_NS {

class ContactStiffnessRecorder {
 public:
  ContactStiffnessRecorder() : sum(0) {}

  // One contact between particles i and j (j may be a ghost: sum has room for ghosts, whose entries
  // the fix ignores; with newton off the owner of a ghost adds the pair to its own particle).
  inline void record(int i, int j, const crush::HertzMindlinStiffness &k) const
  {
    crush::add_contact(sum[i], k);
    crush::add_contact(sum[j], k);
  }

  crush::ContactStiffness *sum;  // per local and ghost atom
};

// Fix dt/stiffness's recorder, if one is attached.
typedef ContactMonitor<ContactStiffnessRecorder> ContactStiffnessMonitor;

}  // namespace LAMMPS_NS

#endif

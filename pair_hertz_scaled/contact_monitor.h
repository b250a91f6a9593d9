/* ----------------------------------------------------------------------
   liggghts-crush: how the contact models hand per-contact results to a fix during the force pass.

   A consumer (fix crush, fix dt/stiffness) owns a recorder and attaches it to its LAMMPS instance;
   every contact model (patches/0009, for the breakage load) or the hertz/scaled normal model (the
   stiffness sums) and fix wall/servo ask their ContactMonitor<Recorder> for it at each contact and
   record into it when one is attached. Each monitor points at its instance's slot in a registry
   (one slot per instance and kind, never removed: std::map keeps it in place), so that the
   per-contact cost without a recorder is one load and one predictable branch, with no call on the
   path that could make the compiler keep the contact's data out of registers. Recorders:
   contact_load_monitor.h (breakage load), contact_stiffness_monitor.h (time step).
------------------------------------------------------------------------- */
#ifndef LMP_CONTACT_MONITOR_H
#define LMP_CONTACT_MONITOR_H

#include <map>

namespace LAMMPS_NS {

class LAMMPS;

template <class Recorder>
class ContactMonitor {
 public:
  explicit ContactMonitor(LAMMPS *lmp) : slot_(&registry()[lmp]) {}

  // The consumer's recorder, or NULL.
  inline const Recorder *recorder() const { return *slot_; }

  // The consumer's recorder from now on (NULL: none). Cheap: a consumer may attach and detach it
  // every step (only the steps it needs are recorded).
  static void attach(LAMMPS *lmp, const Recorder *recorder) { registry()[lmp] = recorder; }

 private:
  // One registry per recorder kind, shared by every translation unit.
  static std::map<LAMMPS *, const Recorder *> &registry()
  {
    static std::map<LAMMPS *, const Recorder *> instance;
    return instance;
  }

  const Recorder *const *slot_;
};

}  // namespace LAMMPS_NS

#endif

/* ----------------------------------------------------------------------
   liggghts-crush: how the contact models hand per-contact results to a fix during the force pass.

   A consumer (fix crush, fix dt/stiffness) owns a recorder and attaches it to its LAMMPS instance;
   the hertz/scaled normal model (and fix wall/servo) ask their ContactMonitor<Recorder> for it at
   each contact and record into it when one is attached. Without a recorder the per-contact cost is
   one integer compare: a monitor re-resolves only when some recorder of its kind was attached or
   detached. Recorders: contact_load_monitor.h (breakage load), contact_stiffness_monitor.h (time step).
------------------------------------------------------------------------- */
#ifndef LMP_CONTACT_MONITOR_H
#define LMP_CONTACT_MONITOR_H

#include <map>

namespace LAMMPS_NS {

class LAMMPS;

template <class Recorder>
class ContactMonitor {
 public:
  explicit ContactMonitor(LAMMPS *lmp) : lmp_(lmp), generation_(-1), recorder_(0) {}

  inline const Recorder *recorder()
  {
    if (generation_ != generation()) resolve();
    return recorder_;
  }

  // The consumer's recorder from now on (NULL: none). Cheap: a consumer may attach and detach it
  // every step (only the steps it needs are recorded).
  static void attach(LAMMPS *lmp, const Recorder *recorder)
  {
    if (recorder) registry()[lmp] = recorder;
    else registry().erase(lmp);
    ++generation();
  }

 private:
  // One registry and one counter per recorder kind, shared by every translation unit.
  static std::map<LAMMPS *, const Recorder *> &registry()
  {
    static std::map<LAMMPS *, const Recorder *> instance;
    return instance;
  }
  static int &generation()
  {
    static int counter = 0;
    return counter;
  }

  // Out of line: the rare path stays out of the contact models' inlined per-contact code.
  __attribute__((noinline)) void resolve()
  {
    const typename std::map<LAMMPS *, const Recorder *>::const_iterator it = registry().find(lmp_);
    recorder_ = it == registry().end() ? 0 : it->second;
    generation_ = generation();
  }

  LAMMPS *lmp_;
  int generation_;
  const Recorder *recorder_;
};

}  // namespace LAMMPS_NS

#endif

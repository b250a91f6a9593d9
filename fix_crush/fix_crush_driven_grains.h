/* ----------------------------------------------------------------------
   liggghts-crush: fix crush and the grains that another fix drives, holds or anchors
   (doc/fix_crush.txt, the inheritance table).

   A fragment copies its mother's per-atom state (fix_crush_replacement.cpp). That is right for a
   temperature; it is wrong for a value that is a position or that makes another fix drive the
   particle. The LIGGGHTS 3.8.0 fixes that do so, and the rule for each:
   - fix insert/stream carries each grain it inserted at a constant velocity, its force zeroed,
     until the grain's release step: a held grain has no free grain's forces (its overlaps grow
     without a response), so it does not break until released; a fragment is never an inserted
     particle, and its release data stay empty (copied, insert/stream would put all fourteen on
     their mother's path);
   - fix spring/self tethers each grain to its anchor: a fragment is tethered to its mother's anchor
     shifted by its own offset (left alone, its anchor is uninitialised memory); computes
     displace/atom and msd keep each particle's original position the same way (their fix store);
   - fix move gives a new atom its own reference position (LIGGGHTS' set_arrays), so fragments keep
     the prescribed motion; its style variable cannot take new atoms and is refused;
   - fix freeze acts on its group, which fragments inherit: they stay frozen;
   - a rigid body (fix multisphere, fix rigid) is refused: 14 spheres are not a piece of a clump.
------------------------------------------------------------------------- */
#ifndef LMP_FIX_CRUSH_DRIVEN_GRAINS_H
#define LMP_FIX_CRUSH_DRIVEN_GRAINS_H

#include <vector>

#include "lmptype.h"
#include "pointers.h"

namespace LAMMPS_NS {

class CrushDrivenGrains : protected Pointers {
 public:
  explicit CrushDrivenGrains(class LAMMPS *lmp) : Pointers(lmp), release_(NULL) {}

  // At init: the fixes that drive or anchor particles. Collective: stops the run, naming the first
  // particle, if a grain of fix crush's group (crush_id, groupbit) belongs to a fix that refuses.
  void find(const char *crush_id, int groupbit);
  // The style of the fix that cannot take the fragments of local particle i, or NULL.
  const char *refusing_fix(int i) const;
  // Stops the run (this processor alone may know): particle tag of fix 'style' cannot break.
  void refuse(const char *crush_id, tagint tag, const char *style) const;
  // Local particle i is still carried by the insertion that created it (fix insert/stream).
  bool held(int i) const;
  // A fix property/atom of a driving fix whose values a fragment must not copy.
  bool driving_property(const class FixPropertyAtom *fix) const;
  // After the fragment's defaults are set: the anchors that other fixes keep for it, its mother's
  // shifted by its offset from her centre (m).
  void anchor(int mother, int fragment, const double *offset) const;

 private:
  void find_fixes();
  void find_origins();
  void refuse_first(const char *crush_id, int groupbit) const;
  bool in_group(int i, const class Fix *fix) const;

  std::vector<class Fix *> bodies_;            // fix multisphere, fix rigid
  std::vector<class Fix *> variable_moves_;    // fix move variable: no new atoms
  std::vector<class FixInsertStream *> streams_;
  class FixPropertyAtom *release_;             // insert/stream's release data (one for all streams)
  std::vector<class Fix *> springs_;           // fix spring/self
  std::vector<class FixStore *> origins_;      // the original positions of compute displace/atom and msd
};

}  // namespace LAMMPS_NS

#endif

/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's check that the fragments of one event are still apart before the
   first force computation after their replacement (doc/fix_crush.txt).

   Fragments are born tangent, each centre at least the sum of two radii from another's. Another fix
   that drives particles may still move them before they first interact: insert/stream, given the
   mother's release data, put all fourteen on her centre, and the pair style then stopped with "no
   contact normal exists". This check names the fragments, their grain and the distance instead.
   It costs one gather of the new fragments' positions at the step after an event step.
------------------------------------------------------------------------- */
#ifndef LMP_FIX_CRUSH_FAMILY_CHECK_H
#define LMP_FIX_CRUSH_FAMILY_CHECK_H

#include <vector>

#include "lmptype.h"
#include "pointers.h"

namespace LAMMPS_NS {

class CrushFamilyCheck : protected Pointers {
 public:
  explicit CrushFamilyCheck(class LAMMPS *lmp) : Pointers(lmp) {}

  // After a replacement at this step: event k's fragments are tags first + nfrag k + (0 .. nfrag - 1).
  void remember(const std::vector<tagint> &mothers, tagint first, int nfrag);
  // Before a force computation (collective): stops the run if two fragments of one event lie closer
  // than the smaller one's radius. The events replaced before this step are then forgotten; a
  // setup (a run's start) checks every event remembered.
  void check(const char *crush_id, bool setup);
  void clear() { families_.clear(); }

 private:
  struct Family {
    tagint mother, first;
    int nfrag;
    bigint step;  // of the replacement
  };
  struct Fragment {
    double tag, radius, x[3];  // gathered as doubles
  };
  std::vector<Fragment> gather() const;
  const Family *family_of(tagint tag) const;
  void report(const char *crush_id, const Family &family, const Fragment &a, const Fragment &b, double distance) const;

  std::vector<Family> families_;
};

}  // namespace LAMMPS_NS

#endif

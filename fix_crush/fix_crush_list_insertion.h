/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's fragments added to the neighbour lists without a rebuild
   ('event_lists insert', doc/fix_crush.txt).

   A fragment lies inside its mother's sphere, so every particle it can touch before the next build
   is one its mother could touch: a neighbour of the mother in the lists. Given each fragment the
   mother's position at the last build shifted by its offset, the distance check that triggers
   builds keeps that guarantee for the fragments too. A grain away from every processor and periodic
   boundary (sent in no swap of the ghost pattern) has no ghost anywhere and no ghost neighbour, so
   its fragments concern this processor alone: they are appended to the owned particles (the ghosts
   move up by as many slots), given list entries against the mother's neighbours and each other,
   and the mother's slot, now holding a fragment, keeps her entries with their histories cleared.
   Walls, primitive or meshes, list a fragment where they listed its mother; its wall contacts are new.
   Anything else (a grain on a boundary, a list or fix this class cannot update) takes LIGGGHTS'
   full rebuild, as before.
------------------------------------------------------------------------- */
#ifndef LMP_FIX_CRUSH_LIST_INSERTION_H
#define LMP_FIX_CRUSH_LIST_INSERTION_H

#include <string>
#include <vector>

#include "pointers.h"

namespace LAMMPS_NS {

class CrushListInsertion : protected Pointers {
 public:
  explicit CrushListInsertion(class LAMMPS *lmp) : Pointers(lmp), list_(NULL), nlocal_before_(0), shift_(0) {}

  // At init: the empty string if every list and fix here can take fragments between builds, else why not.
  std::string unsupported_reason();
  // This processor's mothers (local indices) can be replaced in place: sent in no swap.
  bool can_take(const std::vector<int> &mothers) const;
  // The mothers' spheres lie inside this sub-domain (their fragments need no migration).
  bool inside_subdomain(const std::vector<int> &mothers) const;

  // Before the first fragment exists: the mothers' neighbours are read and the ghosts moved up by
  // (nfrag - 1) per mother, plus one spare slot for the fragment that goes into the mother's place.
  void open(const std::vector<int> &mothers, int nfrag);
  // A mother's fragments: her own slot and the slots appended for her, in order.
  void add_family(int mother, int first_new, int count);
  // After the last fragment: the spare slot closed, lists, hold positions, walls and the atom map set.
  void close();

  // Tests ('check_lists yes'): every touching pair of this processor's particles is in the list,
  // and every particle touching a mesh's triangle in that triangle's list.
  void verify() const;

 private:
  struct Family {
    int mother;                 // her slot, now holding a fragment
    std::vector<int> members;   // the mother's slot, then the appended slots
    std::vector<int> neighbours;  // her list partners before the event (local indices before the shift)
    double x_mother[3];         // her position at the event
    double hold_mother[3];      // her position at the last build
  };
  std::string requester(const class NeighRequest *req) const;
  void read_neighbours();
  void move_ghosts(int from, int to);
  void add_pairs(const Family &family, int member, std::vector<int> &pairs) const;
  bool near(int i, int j) const;
  void append_list(int i, const std::vector<int> &pairs);
  void set_hold_positions();
  void extend_wall_lists();
  void extend_mesh_lists();
  std::vector<class FixMeshSurface *> meshes_with_lists() const;
  void verify_pairs() const;
  void verify_mesh_lists() const;

  class NeighList *list_;       // the granular half list (its history list: list_->listgranhistory)
  std::vector<Family> families_;
  std::vector<int> family_of_;  // per local index before the event: its family, or -1
  int nlocal_before_, shift_;
};

}  // namespace LAMMPS_NS

#endif

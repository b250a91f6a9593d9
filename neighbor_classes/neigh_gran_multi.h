/* 'neighbor SKIN multi' for granular pair styles: the size classes of crush_size_classes.h, owned
   by LIGGGHTS' Neighbor, and their keyword 'neigh_modify size_classes'. */
#ifndef LMP_NEIGH_GRAN_MULTI_H
#define LMP_NEIGH_GRAN_MULTI_H

#include "crush_size_classes.h"

namespace LAMMPS_NS {

class NeighSizeClasses {
 public:
  crush::SizeClassBounds bounds;
  crush::SizeClassBins bins;

  // 'neigh_modify size_classes auto' or 'size_classes N r_1 ... r_N': the words after the keyword;
  // returns how many it took.
  int parse(class LAMMPS *lmp, int narg, char **arg);
};

}  // namespace LAMMPS_NS

#endif

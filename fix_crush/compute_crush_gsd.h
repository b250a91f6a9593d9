/* ----------------------------------------------------------------------
   liggghts-crush: compute crush/gsd, the grain size distribution with the removed volume of a
   fix crush placed as fractal fines, and the grading index I_G (see crush_grading.h and
   doc/compute_crush_gsd.txt).

   compute ID group crush/gsd fix-ID sieves s1 s2 ... [dmax d]

   vector: percent passing by mass at each (downscaled) sieve size, then I_G; each particle is
   downscaled by its own N (fix crush's scale, or its scale_atom);
   scalar: solid volume (m^3), particles plus removed volume, for porosity.
------------------------------------------------------------------------- */
#ifdef COMPUTE_CLASS

ComputeStyle(crush/gsd,ComputeCrushGsd)

#else

#ifndef LMP_COMPUTE_CRUSH_GSD_H
#define LMP_COMPUTE_CRUSH_GSD_H

#include <string>
#include <vector>

#include "compute.h"
#include "crush_grading.h"

namespace LAMMPS_NS {

class ComputeCrushGsd : public Compute {
 public:
  ComputeCrushGsd(class LAMMPS *, int &, int, char **);
  ~ComputeCrushGsd();
  void init();
  double compute_scalar();
  void compute_vector();

 private:
  void parse_arguments(const std::vector<std::string> &args, std::size_t first);
  crush::Grading grading() const;
  void sum_grains(std::vector<double> &sums) const;

  char *fix_id_;
  class FixCrush *fix_;
  std::vector<double> sieves_;
  double dmax_;  // m (downscaled) of the limiting grading; 0: the fix's initial largest grain's d / N
};

}  // namespace LAMMPS_NS

#endif
#endif

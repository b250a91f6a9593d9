/* ----------------------------------------------------------------------
   liggghts-crush: the LIGGGHTS side of crush_keywords.h. A command's arguments are parsed by its
   keyword table; an error goes to error->fix_error() or error->compute_error(), which name the
   style and ID ("ERROR: Fix wall/servo (id walls): keyword 'alpha' expects a value in (0, 1], got '2'").
------------------------------------------------------------------------- */
#ifndef LMP_INPUT_KEYWORD_H
#define LMP_INPUT_KEYWORD_H

#include <string>
#include <vector>

#include "compute.h"
#include "crush_keywords.h"
#include "crush_model_error.h"
#include "error.h"
#include "fix.h"

namespace LAMMPS_NS {

inline std::vector<std::string> words(int narg, char **arg)
{
  return std::vector<std::string>(arg, arg + narg);
}

// Runs parse (which throws crush::ModelError on bad input) and reports its error as the fix's.
template <typename Parse> void fix_input(Fix *fix, Error *error, Parse parse)
{
  try {
    parse();
  } catch (const crush::ModelError &e) {
    error->fix_error(FLERR, fix, e.what());
  }
}

template <typename Parse> void compute_input(Compute *compute, Error *error, Parse parse)
{
  try {
    parse();
  } catch (const crush::ModelError &e) {
    error->compute_error(FLERR, compute, e.what());
  }
}

}  // namespace LAMMPS_NS

#endif

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

// A legal but unlikely value: a warning that names the fix, from proc 0 as LIGGGHTS warns.
inline void fix_warning(Fix *fix, Error *error, int me, const std::string &what)
{
  if (me == 0) error->warning(FLERR, (std::string("Fix ") + fix->style + " (id " + fix->id + "): " + what).c_str());
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

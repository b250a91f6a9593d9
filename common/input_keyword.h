/* ----------------------------------------------------------------------
   liggghts-crush: the LIGGGHTS side of crush_number.h, for the plugin's commands: a keyword's
   value as a finite number, or error->all naming the command, the keyword and what was expected.
------------------------------------------------------------------------- */
#ifndef LMP_INPUT_KEYWORD_H
#define LMP_INPUT_KEYWORD_H

#include <string>

#include "crush_model_error.h"
#include "crush_number.h"
#include "error.h"

namespace LAMMPS_NS {

inline double keyword_number(Error *error, const char *command, const std::string &keyword, const char *text,
                             const std::string &expected)
{
  try {
    return crush::keyword_number(command, keyword, text, expected);
  } catch (const crush::ModelError &e) {
    error->all(FLERR, e.what());
  }
  return 0.0;
}

}  // namespace LAMMPS_NS

#endif

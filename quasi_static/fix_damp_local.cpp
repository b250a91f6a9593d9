/* ----------------------------------------------------------------------
   liggghts-crush: fix damp/local, PFC's local damping (see fix_damp_local.h).
------------------------------------------------------------------------- */
#include "fix_damp_local.h"

#include <cstring>
#include <string>

#include "atom.h"
#include "error.h"
#include "input_keyword.h"
#include "local_damping_law.h"
#include "modify.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixDampLocal::FixDampLocal(LAMMPS *lmp, int narg, char **arg) :
  Fix(lmp, narg, arg), alpha_(-1.0), damp_moments_(true)
{
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "alpha") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "fix damp/local: keyword 'alpha' needs a value in [0, 1)");
      alpha_ = keyword_number(error, "fix damp/local", "alpha", arg[iarg + 1], "a value in [0, 1)");
      if (alpha_ < 0.0 || alpha_ >= 1.0)
        error->all(FLERR, "fix damp/local: 'alpha' must be in [0, 1) (PFC's default is 0.7, "
                          "quasi-static runs of the paper use 0.05)");
      iarg += 2;
    } else if (strcmp(arg[iarg], "moments") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "fix damp/local: keyword 'moments' needs 'yes' or 'no'");
      if (strcmp(arg[iarg + 1], "yes") == 0) damp_moments_ = true;
      else if (strcmp(arg[iarg + 1], "no") == 0) damp_moments_ = false;
      else error->all(FLERR, "fix damp/local: keyword 'moments' expects 'yes' or 'no'");
      iarg += 2;
    } else {
      const std::string msg = std::string("fix damp/local: unknown keyword '") + arg[iarg] +
                              "' (expected 'alpha' or 'moments')";
      error->all(FLERR, msg.c_str());
    }
  }
  if (alpha_ < 0.0) error->all(FLERR, "fix damp/local: keyword 'alpha' is required (a value in [0, 1))");
  if (damp_moments_ && !atom->torque_flag)
    error->all(FLERR, "fix damp/local: 'moments yes' needs an atom style with torque (granular)");
}

int FixDampLocal::setmask()
{
  return POST_FORCE;
}

void FixDampLocal::init()
{
  check_order();
}

// PFC damps the total unbalanced force: every fix that adds forces must run before this one.
void FixDampLocal::check_order() const
{
  bool after_me = false;
  for (int k = 0; k < modify->nfix; k++) {
    if (modify->fix[k] == this) {
      after_me = true;
      continue;
    }
    if (after_me && (modify->fmask[k] & POST_FORCE)) {
      const std::string msg = std::string("fix damp/local must be defined after fix ") +
                              modify->fix[k]->id + " (" + modify->fix[k]->style +
                              "), which adds forces: local damping acts on the total force";
      error->all(FLERR, msg.c_str());
    }
  }
}

void FixDampLocal::setup(int vflag)
{
  post_force(vflag);
}

void FixDampLocal::post_force(int)
{
  double **f = atom->f, **v = atom->v;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; k++) f[i][k] = crush::locally_damped(f[i][k], v[i][k], alpha_);
  }
  if (!damp_moments_) return;
  double **torque = atom->torque, **omega = atom->omega;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; k++) torque[i][k] = crush::locally_damped(torque[i][k], omega[i][k], alpha_);
  }
}

/* ----------------------------------------------------------------------
   liggghts-crush: fix damp/local, PFC's local damping (see fix_damp_local.h).
------------------------------------------------------------------------- */
#include "fix_damp_local.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "input_keyword.h"
#include "local_damping_law.h"
#include "modify.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixDampLocal::FixDampLocal(LAMMPS *lmp, int narg, char **arg) :
  Fix(lmp, narg, arg), alpha_(-1.0), damp_moments_(true)
{
  fix_input(this, error, [&] {
    crush::KeywordTable t;
    // PFC's default alpha is 0.7; the quasi-static runs of the paper use 0.05
    t.number("alpha", "a value in [0, 1)", crush::in_range(0.0, 1.0, false), alpha_, true)
     .yes_no("moments", damp_moments_);
    t.parse(words(narg, arg), 3);
    if (damp_moments_ && !atom->torque_flag)
      throw crush::ModelError("'moments yes' needs an atom style with torque (granular)");
  });
  if (alpha_ > 0.8)
    fix_warning(this, error, comm->me, "alpha above 0.8: the damping then shapes the response (PFC's default is "
                                       "0.7, the paper's quasi-static runs use 0.05)");
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

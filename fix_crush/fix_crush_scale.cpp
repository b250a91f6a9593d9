/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's upscaling factor per particle ('scale_atom', doc/fix_crush.txt).

   Eq. 10's N says how much larger a model grain is than the sand grain it stands for. A refined
   chamber holds fine grains near a penetrometer and coarse ones far from it, each zone with its
   own N: the deck keeps N per particle in a scalar fix property/atom that the user names, sets per
   region or type (set ... property/atom), and that restarts carry. Fragments copy it from their
   mother as they copy every fix property/atom (fix_crush_replacement.cpp). Eq. 10's size effect,
   the comminution limit (dmin is a model diameter at the deck's N: a particle may break while
   d N / N_i >= dmin, i.e. while its sand size d / N_i >= dmin / N) and the grading (d / N_i) read
   each particle's own N. Without 'scale_atom' every particle has the deck's N ('scale').
------------------------------------------------------------------------- */
#include "fix_crush.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "atom.h"
#include "error.h"
#include "fix_property_atom.h"
#include "modify.h"

using namespace LAMMPS_NS;

double FixCrush::scale_of(int i) const
{
  return fix_scale_ ? fix_scale_->vector_atom[i] : settings_.scale_factor;
}

// At init: the user's fix property/atom, found by the name 'scale_atom' gives (a scalar).
void FixCrush::find_scale()
{
  fix_scale_ = NULL;
  if (settings_.scale_atom.empty()) return;
  Fix *fix = modify->find_fix_property(settings_.scale_atom.c_str(), "property/atom", "scalar", 0, 0, style, false);
  fix_scale_ = dynamic_cast<FixPropertyAtom *>(fix);
  if (!fix_scale_)
    error->fix_error(FLERR, this, ("keyword 'scale_atom': no scalar fix property/atom named '" + settings_.scale_atom +
                                   "': define 'fix ID all property/atom " + settings_.scale_atom +
                                   " scalar yes no no N' before fix crush and set each particle's N").c_str());
}

// Every particle of the group has a finite N > 0 (a zero left by an unset property would divide by
// zero in eq. 10): the run stops naming the first that has not. One reduction, with 'scale_atom' only.
void FixCrush::check_scales() const
{
  if (!fix_scale_) return;
  const int first_all = first_failing([this](int i) {
    const double n = fix_scale_->vector_atom[i];
    return (atom->mask[i] & groupbit) && !(n > 0.0 && std::isfinite(n));
  });
  if (!first_all) return;
  const int i = atom->map(first_all);
  if (i >= 0 && i < atom->nlocal) {
    char msg[512];
    snprintf(msg, sizeof(msg), "Fix crush (id %s): keyword 'scale_atom': particle %d has %s = %g; each particle's "
             "upscaling factor must be finite and > 0 (set ... property/atom %s N)", id, first_all,
             settings_.scale_atom.c_str(), fix_scale_->vector_atom[i], settings_.scale_atom.c_str());
    error->one(FLERR, msg);
  }
  MPI_Barrier(world);  // the owner stops the run
}

// The smallest N of the group's particles on all processors (the deck's N without 'scale_atom').
double FixCrush::smallest_scale() const
{
  if (!fix_scale_) return settings_.scale_factor;
  double smallest = 1e300, smallest_all = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) smallest = std::min(smallest, fix_scale_->vector_atom[i]);
  MPI_Allreduce(&smallest, &smallest_all, 1, MPI_DOUBLE, MPI_MIN, world);
  return smallest_all < 1e300 ? smallest_all : settings_.scale_factor;
}

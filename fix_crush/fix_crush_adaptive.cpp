/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's exact adaptive check ('every adaptive'): the steps on which no grain
   can reach its limit, proved by the bound of crush_check_bound.h, are neither recorded nor checked.
   At each check the fix stores every particle's position (and the walls' and the periodic box's) and
   the smallest displacement that could bring a grain to its limit; on each later step it measures
   the largest displacement since the check, and checks again once that reaches the allowance.
------------------------------------------------------------------------- */
#include "fix_crush.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "atom.h"
#include "crush_check_bound.h"
#include "domain.h"
#include "error.h"
#include "fix_property_atom.h"
#include "modify.h"

using namespace LAMMPS_NS;

namespace {
const int nwall_positions = 6;  // fix wall/servo: f_walls[1..6], the wall positions
}  // namespace

// The walls whose motion the bound covers: fix wall/servo's, whose positions it publishes. A mesh
// moved by fix move/mesh is not covered: refuse rather than miss an event.
void FixCrush::find_moving_walls()
{
  wall_ids_.clear();
  for (int k = 0; k < modify->nfix; k++) {
    const char *style = modify->fix[k]->style;
    if (strcmp(style, "wall/servo") == 0) wall_ids_.push_back(modify->fix[k]->id);
    else if (strncmp(style, "move/mesh", 9) == 0)
      error->fix_error(FLERR, this, "keyword 'every adaptive' bounds the motion of fix wall/servo walls only, "
                                    "and fix move/mesh moves a mesh: use 'every 1' (or 'every N')");
  }
}

// Wall k of init(), or NULL once unfixed: by ID, since 'run ... pre no' after an unfix skips init().
Fix *FixCrush::wall(std::size_t k) const
{
  const int ifix = modify->find_fix(wall_ids_[k].c_str());
  return ifix < 0 ? NULL : modify->fix[ifix];
}

// growth_i of every local particle that may break (crush_check_bound.h), with the smallest radius
// among the particles it may touch before the next reneighboring (owned and ghost).
void FixCrush::update_ratio_growth()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const double *radius = atom->radius;
  const int *type = atom->type;
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < nall; i++) smallest = std::min(smallest, radius[i]);
  ratio_growth_.assign(nlocal, 0.0);
  for (int i = 0; i < nlocal; i++)
    if (breakable(i))
      ratio_growth_[i] = crush::ratio_growth(ratio_coefficient_[type[i]], strength_term_[i], radius[i], smallest);
}

// Positions at this check, for the displacements of the following steps. Called in pre_force: the
// walls have not yet moved for the next step.
void FixCrush::store_check_reference()
{
  const int nlocal = atom->nlocal;
  double **x = atom->x;
  reference_x_.resize(3 * static_cast<std::size_t>(nlocal));
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 3; k++) reference_x_[3 * i + k] = x[i][k];
  wall_reference_.assign(nwall_positions * wall_ids_.size(), 0.0);
  for (std::size_t w = 0; w < wall_ids_.size(); w++)
    if (Fix *f = wall(w))
      for (int k = 0; k < nwall_positions; k++) wall_reference_[nwall_positions * w + k] = f->compute_vector(k);
  for (int k = 0; k < 3; k++) box_reference_[k] = domain->prd[k];
}

// D: the largest displacement of any particle, wall or periodic image since the last check, over
// all processors.
double FixCrush::largest_displacement() const
{
  const int nlocal = atom->nlocal;
  double **x = atom->x;
  const double *ref = reference_x_.data();
  double largest_squared = 0.0;
  for (int i = 0; i < nlocal; i++) {
    const double dx = x[i][0] - ref[3 * i], dy = x[i][1] - ref[3 * i + 1], dz = x[i][2] - ref[3 * i + 2];
    const double d2 = dx * dx + dy * dy + dz * dz;
    largest_squared = d2 > largest_squared ? d2 : largest_squared;
  }
  double largest = std::sqrt(largest_squared);
  // a wall unfixed since the check touches nothing any more
  for (std::size_t w = 0; w < wall_ids_.size(); w++)
    if (Fix *f = wall(w))
      for (int k = 0; k < nwall_positions; k++)
        largest = std::max(largest, std::fabs(f->compute_vector(k) - wall_reference_[nwall_positions * w + k]));
  // A periodic image moves with the box length as well.
  for (int k = 0; k < 3; k++)
    if (domain->periodicity[k]) largest = std::max(largest, std::fabs(domain->prd[k] - box_reference_[k]));
  double all = 0.0;
  MPI_Allreduce(&largest, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return all;
}

// After a check: the smallest allowance over all particles that may break.
void FixCrush::schedule_next_check()
{
  double **data = fix_data_->array_atom;
  double allowed = std::numeric_limits<double>::infinity();
  for (int i = 0; i < atom->nlocal; i++) {
    const double growth = ratio_growth_[i], ratio = data[i][RATIO];
    if (growth <= 0.0) continue;
    // ratio^(2/3) >= ratio below the limit: a bound without the cube root skips most particles.
    if (ratio < 1.0 && (1.0 - ratio) / (2.0 * growth) >= allowed) continue;
    allowed = std::min(allowed, crush::allowed_displacement(ratio, growth));
  }
  MPI_Allreduce(&allowed, &allowed_displacement_, 1, MPI_DOUBLE, MPI_MIN, world);
}

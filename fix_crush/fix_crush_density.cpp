/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's true densities ('fragment_density scaled', crush_fragment_density.h).

   Scaled fragments carry a density that only their inertia sees. Each particle's true density lives
   in a restartable fix property/atom (crush_true_density_<ID>, a dump reads it as
   f_crush_true_density_<ID>): a grain's own density until it breaks, its mother's true density after.
   Volumes (porosity, the grading, the removed volume) never involve density; the outputs that weigh
   mass use the true one (output 8). With 'fragment_density true' none of this exists.
------------------------------------------------------------------------- */
#include "fix_crush.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "crush_constants.h"
#include "fix_property_atom.h"
#include "modify.h"

using namespace LAMMPS_NS;

namespace {
bool scaled(const crush::CrushSettings &settings)
{
  return settings.fragment_density == crush::FragmentDensity::scaled;
}
}  // namespace

// In post_create: the per-atom true density, 0 until the particle is first seen (fill_true_densities).
void FixCrush::create_true_density()
{
  if (!scaled(settings_)) return;
  const std::string name = std::string("crush_true_density_") + id;
  true_density_id_ = new char[name.size() + 1];
  strcpy(true_density_id_, name.c_str());
  const char *fixarg[9] = {true_density_id_, "all", "property/atom", true_density_id_, "scalar", "yes", "no", "no",
                           "0."};
  modify->add_fix(9, const_cast<char **>(fixarg));
  find_true_density();
}

void FixCrush::find_true_density()
{
  if (!true_density_id_) return;
  fix_true_density_ = static_cast<FixPropertyAtom *>(
      modify->find_fix_property(true_density_id_, "property/atom", "scalar", 0, 0, style));
}

// After reneighboring: a particle without a true density (a grain never broken, inserted, or read
// from a run without scaling) has its own.
void FixCrush::fill_true_densities()
{
  if (!fix_true_density_) return;
  double *rho_true = fix_true_density_->vector_atom;
  for (int i = 0; i < atom->nlocal; i++)
    if (!(rho_true[i] > 0.0)) rho_true[i] = atom->density[i];
}

double FixCrush::true_density(int i) const
{
  if (!fix_true_density_) return atom->density[i];
  const double rho = fix_true_density_->vector_atom[i];
  return rho > 0.0 ? rho : atom->density[i];
}

// The group's particles' mass at their true densities (kg), over all processors.
double FixCrush::true_mass() const
{
  double mass = 0.0, mass_all = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) mass += true_density(i) * crush::sphere_volume(2.0 * atom->radius[i]);
  MPI_Allreduce(&mass, &mass_all, 1, MPI_DOUBLE, MPI_SUM, world);
  return mass_all;
}

// The largest density / true density of the group (1 without scaling or fragments), over all processors.
double FixCrush::largest_density_scale() const
{
  double scale = 1.0, scale_all = 1.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) scale = std::max(scale, atom->density[i] / true_density(i));
  MPI_Allreduce(&scale, &scale_all, 1, MPI_DOUBLE, MPI_MAX, world);
  return scale_all;
}

// The smallest r sqrt(rho) of the particles present, over all processors (1e300 without particles).
double FixCrush::smallest_rayleigh_product() const
{
  double product = 1e300, product_all = 1e300;
  for (int i = 0; i < atom->nlocal; i++) product = std::min(product, atom->radius[i] * std::sqrt(atom->density[i]));
  MPI_Allreduce(&product, &product_all, 1, MPI_DOUBLE, MPI_MIN, world);
  return product_all;
}

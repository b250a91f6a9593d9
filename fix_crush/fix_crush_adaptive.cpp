/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's exact adaptive check ('every adaptive'): the steps on which no grain
   can reach its limit, proved by the bound of crush_check_bound.h, are neither recorded nor checked.
   At each check the fix stores every particle's position (and the walls', the mesh nodes' and the
   periodic box's) and the smallest displacement that could bring a grain to its limit; on each later
   step it measures the largest displacement since the check, and checks again once that reaches the
   allowance.
------------------------------------------------------------------------- */
#include "fix_crush.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "atom.h"
#include "crush_check_bound.h"
#include "abstract_mesh.h"
#include "domain.h"
#include "error.h"
#include "fix_mesh.h"
#include "fix_property_atom.h"
#include "modify.h"

using namespace LAMMPS_NS;

namespace {
const int nwall_positions = 6;  // fix wall/servo: f_walls[1..6], the wall positions
}  // namespace

// The walls whose motion the bound covers: fix wall/servo's, whose positions it publishes, and every
// mesh (fix mesh/surface...), whose nodes fix move/mesh may move: a static one adds nothing.
void FixCrush::find_moving_walls()
{
  wall_ids_.clear();
  mesh_ids_.clear();
  for (int k = 0; k < modify->nfix; k++) {
    const char *style = modify->fix[k]->style;
    if (strcmp(style, "wall/servo") == 0) wall_ids_.push_back(modify->fix[k]->id);
    else if (strncmp(style, "mesh/surface", 12) == 0) mesh_ids_.push_back(modify->fix[k]->id);
  }
}

// Mesh k of init(), or NULL once unfixed.
AbstractMesh *FixCrush::mesh(std::size_t k) const
{
  const int ifix = modify->find_fix(mesh_ids_[k].c_str());
  return ifix < 0 ? NULL : static_cast<FixMesh *>(modify->fix[ifix])->mesh();
}

// Every node of mesh k by element ID (3 coordinates a node), the same on every processor: each owned
// element writes its own, one sum gathers them (meshes of a few thousand elements: a tool, a pile).
std::vector<double> FixCrush::mesh_nodes(std::size_t k) const
{
  AbstractMesh *m = mesh(k);
  if (!m) return std::vector<double>();
  const int per_element = 3 * m->numNodes();
  int largest_id = -1, largest_all = -1;
  for (int i = 0; i < m->sizeLocal(); i++) largest_id = std::max(largest_id, m->id_slow(i));
  MPI_Allreduce(&largest_id, &largest_all, 1, MPI_INT, MPI_MAX, world);
  std::vector<double> local(static_cast<std::size_t>(largest_all + 1) * per_element, 0.0), all(local.size(), 0.0);
  for (int i = 0; i < m->sizeLocal(); i++)
    for (int j = 0; j < m->numNodes(); j++)
      m->node_slow(i, j, &local[static_cast<std::size_t>(m->id_slow(i)) * per_element + 3 * j]);
  MPI_Allreduce(local.data(), all.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_SUM, world);
  return all;
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
  mesh_reference_.assign(mesh_ids_.size(), std::vector<double>());
  for (std::size_t k = 0; k < mesh_ids_.size(); k++) mesh_reference_[k] = mesh_nodes(k);
}

// The largest displacement of an owned element's nodes since the check (this processor's).
double FixCrush::largest_mesh_displacement() const
{
  double largest = 0.0;
  for (std::size_t k = 0; k < mesh_ids_.size(); k++) {
    AbstractMesh *m = mesh(k);
    if (!m) continue;
    const std::vector<double> &ref = mesh_reference_[k];
    const int per_element = 3 * m->numNodes();
    for (int i = 0; i < m->sizeLocal(); i++)
      for (int j = 0; j < m->numNodes(); j++) {
        const std::size_t at = static_cast<std::size_t>(m->id_slow(i)) * per_element + 3 * j;
        if (at + 3 > ref.size()) return std::numeric_limits<double>::infinity();  // a new element: check
        double x[3];
        m->node_slow(i, j, x);
        const double dx = x[0] - ref[at], dy = x[1] - ref[at + 1], dz = x[2] - ref[at + 2];
        largest = std::max(largest, std::sqrt(dx * dx + dy * dy + dz * dz));
      }
  }
  return largest;
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
  largest = std::max(largest, largest_mesh_displacement());
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

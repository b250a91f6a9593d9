/* ----------------------------------------------------------------------
   liggghts-crush: compute crush/gsd (see compute_crush_gsd.h).
------------------------------------------------------------------------- */
#include "compute_crush_gsd.h"

#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "crush_constants.h"
#include "crush_grading.h"
#include "crush_model_error.h"
#include "error.h"
#include "fix_crush.h"
#include "input_keyword.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeCrushGsd::ComputeCrushGsd(LAMMPS *lmp, int &iarg, int narg, char **arg) :
  Compute(lmp, iarg, narg, arg), fix_id_(NULL), fix_(NULL), dmax_(0.0)
{
  compute_input(this, error, [&] { parse_arguments(words(narg, arg), iarg); });
  iarg = narg;

  scalar_flag = vector_flag = 1;
  size_vector = static_cast<int>(sieves_.size()) + 1;
  extscalar = extvector = 0;
  vector = new double[size_vector];
}

ComputeCrushGsd::~ComputeCrushGsd()
{
  delete[] fix_id_;
  delete[] vector;
}

// fix-ID sieves s1 s2 ... [dmax d]; throws crush::ModelError naming the keyword.
void ComputeCrushGsd::parse_arguments(const std::vector<std::string> &args, std::size_t first)
{
  if (first + 2 >= args.size() || args[first + 1] != "sieves")
    throw crush::ModelError("expected 'compute ID group crush/gsd fix-ID sieves s1 s2 ... [dmax d]'");
  fix_id_ = new char[args[first].size() + 1];
  strcpy(fix_id_, args[first].c_str());
  crush::KeywordTable t;
  t.ascending("sieves", "ascending sizes > 0 (m)", sieves_, true);
  t.number("dmax", "one size > 0 (m)", crush::positive(), dmax_);
  t.parse(args, first + 1);
}

void ComputeCrushGsd::init()
{
  const int ifix = modify->find_fix(fix_id_);
  if (ifix < 0 || strcmp(modify->fix[ifix]->style, "crush") != 0)
    error->all(FLERR, (std::string("compute crush/gsd: '") + fix_id_ + "' is not the ID of a fix crush").c_str());
  fix_ = static_cast<FixCrush *>(modify->fix[ifix]);
}

// The grading in sand sizes: each particle downscaled by its own N (fix crush's scale or scale_atom),
// weighed by its model volume (the volume of sand it stands for).
crush::Grading ComputeCrushGsd::grading() const
{
  return crush::Grading(sieves_, 1.0, fix_->settings().fines_dimension);
}

// sums = {volume passing each sieve..., volume, volume x size}, added over processors.
void ComputeCrushGsd::sum_grains(std::vector<double> &sums) const
{
  const crush::Grading sand = grading();
  crush::GradingSums local = sand.empty_sums();
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) {
      const double d = 2.0 * atom->radius[i];
      sand.add_volume(d / fix_->scale_of(i), crush::sphere_volume(d), local);
    }
  std::vector<double> packed(local.volume_passing);
  packed.push_back(local.volume);
  packed.push_back(local.volume_times_size);
  sums.assign(packed.size(), 0.0);
  MPI_Allreduce(packed.data(), sums.data(), static_cast<int>(packed.size()), MPI_DOUBLE, MPI_SUM, world);
}

double ComputeCrushGsd::compute_scalar()
{
  if (!fix_) init();  // 'run ... pre no' right after the compute was defined skips init()
  invoked_scalar = update->ntimestep;
  std::vector<double> sums;
  sum_grains(sums);
  scalar = sums[sieves_.size()] + fix_->removed_volume();
  return scalar;
}

void ComputeCrushGsd::compute_vector()
{
  if (!fix_) init();
  invoked_vector = update->ntimestep;
  std::vector<double> packed;
  sum_grains(packed);
  const crush::Grading sand = grading();
  crush::GradingSums sums = sand.empty_sums();
  for (std::size_t k = 0; k < sieves_.size(); k++) sums.volume_passing[k] = packed[k];
  sums.volume = packed[sieves_.size()];
  sums.volume_times_size = packed[sieves_.size() + 1];
  const double dmax = dmax_ > 0.0 ? dmax_ : fix_->initial_largest_size();
  try {
    const std::vector<double> passing = sand.percent_passing(sums, fix_->removed_volume(), fix_->smallest_fragment_size());
    for (std::size_t k = 0; k < passing.size(); k++) vector[k] = passing[k];
    vector[sieves_.size()] = sand.grading_index(sums, fix_->removed_volume(), fix_->smallest_fragment_size(), dmax);
  } catch (const crush::ModelError &e) {
    error->all(FLERR, (std::string("compute crush/gsd: ") + e.what()).c_str());
  }
}

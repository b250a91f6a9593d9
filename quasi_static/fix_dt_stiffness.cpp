/* ----------------------------------------------------------------------
   liggghts-crush: fix dt/stiffness (see fix_dt_stiffness.h).
------------------------------------------------------------------------- */
#include "fix_dt_stiffness.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "crush_model_error.h"
#include "error.h"
#include "type_materials.h"
#include "fix_wall_servo.h"
#include "force.h"
#include "input_keyword.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_gran.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixDtStiffness::FixDtStiffness(LAMMPS *lmp, int narg, char **arg) :
  Fix(lmp, narg, arg), fraction_(-1.0), growth_(1.01), dt_max_(1e300), dt_start_(0.0), every_(1),
  stiffening_(false), warned_(false), updating_(false), published_(false)
{
  fix_input(this, error, [&] {
    long every = 1;
    crush::KeywordTable t;
    t.number("fraction", "a value in (0, 1] (0.5 is safe)", crush::open_closed(0.0, 1.0), fraction_, true)
     .integer("every", "a number of steps >= 1", 1, every)
     .number("growth", "a factor in (1, 10]", crush::open_closed(1.0, 10.0), growth_)
     .number("max", "a time step in (0, 1] s", crush::open_closed(0.0, 1.0), dt_max_);
    t.parse(words(narg, arg), 3);
    every_ = static_cast<int>(every);
  });
  if (fraction_ > 0.5)
    fix_warning(this, error, comm->me, "fraction above 0.5: the step comes close to the stability limit of the "
                                       "stiffest contact (0.5 is safe)");
  if (growth_ > 1.5)
    fix_warning(this, error, comm->me, "growth above 1.5: after a stiff contact opens the step may jump past what "
                                       "the next contact allows");
  if (!atom->radius_flag || !atom->rmass_flag)
    error->fix_error(FLERR, this, "needs atom_style granular (radius and mass)");
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 0;
  restart_global = 1;
}

FixDtStiffness::~FixDtStiffness()
{
  ContactStiffnessMonitor::attach(lmp, NULL);
}

int FixDtStiffness::setmask()
{
  return PRE_FORCE | END_OF_STEP;
}

// eq. 8-9 factors of every type pair, from the types' elastic constants.
void FixDtStiffness::init()
{
  if (!force->pair || strncmp(force->pair_style, "gran", 4) != 0) error->fix_error(FLERR, this, "needs pair_style gran");
  // hertz/scaled publishes every contact's stiffness during the force pass; other contact models
  // leave the fix to walk the neighbour list itself.
  PairGran *pair = static_cast<PairGran *>(force->pair_match("gran", 0));
  published_ = pair && pair->contact_match("normal", "hertz/scaled");
  if (modify->n_fixes_style(style) > 1) error->fix_error(FLERR, this, "only one fix dt/stiffness can set the time step");
  const int ntypes = atom->ntypes;
  coefficients_.assign((ntypes + 1) * (ntypes + 1), crush::HertzMindlinCoefficients{0.0, 0.0});
  try {
    for (int a = 1; a <= ntypes; a++)
      for (int b = 1; b <= ntypes; b++)
        coefficients_[a * (ntypes + 1) + b] = crush::hertz_mindlin_coefficients(
            type_shear_material(modify, ntypes, a, style), type_shear_material(modify, ntypes, b, style));
  } catch (const crush::ModelError &e) {
    error->fix_error(FLERR, this, (std::string("youngsModulus/poissonsRatio: ") + e.what()).c_str());
  }
}

// The setup's force pass always feeds an update (setup below).
void FixDtStiffness::setup_pre_force(int)
{
  collect_stiffness(true);
}

void FixDtStiffness::setup(int)
{
  update_time_step();
  if (dt_start_ == 0.0) dt_start_ = update->dt;  // the first run's: chunked runs keep it
}

// Every M steps; at every step with a fresh neighbour list, since particles appear (crushing
// fragments, insertions) only then and a new small particle may need a smaller step at once; and at
// the step after an update that shrank the step by more than the growth factor: contacts stiffening
// that fast (fragments pressed together) are followed step by step until they settle. Decided before
// the force pass (the neighbour list is built by then), so that only those passes record.
void FixDtStiffness::pre_force(int)
{
  collect_stiffness(update->ntimestep % every_ == 0 || neighbor->atoms_added(update->ntimestep) || stiffening_);
}

void FixDtStiffness::end_of_step()
{
  if (updating_) update_time_step();
}

// Clears the sums and attaches them to the contact model for this step's force pass, or detaches
// them (the pass then costs what it costs without this fix).
void FixDtStiffness::collect_stiffness(bool update_now)
{
  updating_ = update_now;
  if (updating_) stiffness_.assign(atom->nlocal + atom->nghost, crush::ContactStiffness());
  recorder_.sum = stiffness_.data();
  ContactStiffnessMonitor::attach(lmp, updating_ && published_ ? &recorder_ : NULL);
}

void FixDtStiffness::update_time_step()
{
  const int nlocal = atom->nlocal;
  if (!published_) add_pair_contacts();
  for (int i = 0; i < modify->nfix; i++)
    if (strcmp(modify->fix[i]->style, "wall/servo") == 0)
      static_cast<FixWallServo *>(modify->fix[i])->add_contact_stiffness(stiffness_);
  double smallest = 1e300, radius = 0.0;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double dt = crush::critical_step(atom->rmass[i], stiffness_[i]);
    if (dt < smallest) {
      smallest = dt;
      radius = atom->radius[i];
    }
  }
  double smallest_all = 1e300;
  MPI_Allreduce(&smallest, &smallest_all, 1, MPI_DOUBLE, MPI_MIN, world);
  // Without any contact the step stays: nothing says how stiff the first contact will be.
  const double previous = update->dt;
  if (smallest_all < 1e300)
    set_time_step(crush::next_time_step(update->dt, smallest_all, fraction_, growth_, dt_max_));
  stiffening_ = update->dt * growth_ < previous;
  if (!warned_ && dt_start_ > 0.0 && update->dt < 1e-3 * dt_start_) warn_collapse(smallest == smallest_all ? radius : 0.0);
}

// Without hertz/scaled: every overlapping pair of the pair style's half list, as the force pass of
// hertz/scaled records them (newton off: a pair with a ghost is listed on both processors, each adds
// it to its own particle).
void FixDtStiffness::add_pair_contacts()
{
  NeighList *list = force->pair->list;
  if (!list) return;
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, stride = atom->ntypes + 1;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double reach = radius[i] + radius[j];
      const double distance_sq = dx * dx + dy * dy + dz * dz;
      if (distance_sq >= reach * reach) continue;
      const double overlap = reach - std::sqrt(distance_sq);
      const double diameter_term = crush::diameter_term_from_radii(radius[i], radius[j]);
      const crush::HertzMindlinCoefficients &c = coefficients_[type[i] * stride + type[j]];
      if (i < nlocal) crush::add_contact(stiffness_[i], c, diameter_term, overlap);
      if (j < nlocal) crush::add_contact(stiffness_[j], c, diameter_term, overlap);
    }
  }
}

// Once: a step a thousand times below the starting one means tiny particles in contact (a
// crushing cascade without a comminution limit); a ramp counted in steps then loads in no time.
void FixDtStiffness::warn_collapse(double local_radius)
{
  warned_ = true;
  double radius = 0.0;
  MPI_Allreduce(&local_radius, &radius, 1, MPI_DOUBLE, MPI_MAX, world);
  if (comm->me != 0) return;
  char msg[512];
  snprintf(msg, sizeof(msg),
           "fix dt/stiffness: time step %g s, below 1/1000 of the %g s at the start: a particle of "
           "radius %g m sets it; a load ramp counted in steps now loads in almost no physical time (set "
           "'dmin' in fix crush to stop fragments breaking further)",
           update->dt, dt_start_, radius);
  error->warning(FLERR, msg);
}

// As LAMMPS' fix dt/reset: close the time account at the old step, then tell the pair style and the
// fixes (integrators cache dt).
void FixDtStiffness::set_time_step(double dt)
{
  if (dt == update->dt) return;
  update->update_time();
  update->dt = dt;
  force->pair->reset_dt();
  for (int i = 0; i < modify->nfix; i++) modify->fix[i]->reset_dt();
}

// LIGGGHTS 3.8.0's restart header holds neither the time step nor the elapsed time: this fix, which
// sets the step, carries both, so that a resumed run goes on with the step and the clock it had.
namespace {
const int kRestartVersion = 1;
struct RestartState {
  int version;
  double dt, time, dt_start;
  int warned;
};
}  // namespace

void FixDtStiffness::write_restart(FILE *fp)
{
  const RestartState state = {kRestartVersion, update->dt, update->atime + (update->ntimestep - update->atimestep) * update->dt,
                              dt_start_, warned_ ? 1 : 0};
  if (comm->me == 0) {
    int size = sizeof(RestartState);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(&state, sizeof(RestartState), 1, fp);
  }
}

void FixDtStiffness::restart(char *buf)
{
  RestartState state;
  std::memcpy(&state, buf, sizeof(RestartState));
  if (state.version != kRestartVersion) {
    char msg[256];
    snprintf(msg, sizeof(msg), "the restart file's fix dt/stiffness section is version %d; this build reads version %d",
             state.version, kRestartVersion);
    error->fix_error(FLERR, this, msg);
  }
  if (!(state.dt > 0.0) || !std::isfinite(state.time))
    error->fix_error(FLERR, this, "the restart file's time step or time is not a finite positive number");
  update->dt = state.dt;
  update->atime = state.time;
  update->atimestep = update->ntimestep;
  dt_start_ = state.dt_start;
  warned_ = state.warned != 0;
}

double FixDtStiffness::compute_scalar()
{
  return update->dt;
}

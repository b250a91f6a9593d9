/* ----------------------------------------------------------------------
   liggghts-crush: fix wall/servo (see fix_wall_servo.h).
------------------------------------------------------------------------- */
#include "fix_wall_servo.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "crush_load_ramp.h"
#include "crush_model_error.h"
#include "error.h"
#include "type_materials.h"
#include "force.h"
#include "input_keyword.h"
#include "hertz_mindlin_scaled_law.h"
#include "memory.h"
#include "modify.h"
#include "servo_wall_law.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
const char *const kAxis = "xyz";

void expect(Error *error, bool ok, const std::string &message)
{
  if (!ok) error->all(FLERR, ("fix wall/servo: " + message).c_str());
}
}  // namespace

FixWallServo::FixWallServo(LAMMPS *lmp, int narg, char **arg) :
  Fix(lmp, narg, arg), wall_type_(0), sigma_start_(1e3), sigma_max_(0.0), load_rate_(0.0), sigma_ref_(1e3),
  target_(0.0), alpha_(0.5), max_step_(0.0), progress_percent_(0.0), ramp_done_(0.0),
  next_report_(0.0), ramp_wall_start_(0.0), ramp_started_steps_(0.0), ramp_started_(false), monitor_(lmp)
{
  expect(error, narg >= 9, "expected 'fix ID group wall/servo xlo xhi ylo yhi zlo zhi type T x MODE y MODE z MODE'");
  const char *const wall_names[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
  for (int k = 0; k < 6; k++) wall_[k] = keyword_number(error, "fix wall/servo", wall_names[k], arg[3 + k], "a position (m)");
  for (int a = 0; a < 3; a++) {
    expect(error, wall_[2 * a + 1] > wall_[2 * a], std::string("the ") + kAxis[a] + "hi wall must lie above the " +
                                                       kAxis[a] + "lo wall");
    mode_[a] = FIXED;
    value_[a] = 0.0;
    force_[2 * a] = force_[2 * a + 1] = 0.0;
    last_move_[a] = 0.0;
  }
  int iarg = 9;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "type") {
      expect(error, iarg + 1 < narg, "keyword 'type' expects the wall's atom type");
      wall_type_ = force->inumeric(FLERR, arg[iarg + 1]);
      expect(error, wall_type_ >= 1 && wall_type_ <= atom->ntypes, "keyword 'type' expects an atom type 1..ntypes");
      iarg += 2;
    } else if (key == "x" || key == "y" || key == "z") {
      parse_mode(key[0] - 'x', narg, arg, iarg);
    } else if (key == "ramp") {
      expect(error, iarg + 3 < narg, "keyword 'ramp' expects sigma_start sigma_max load_rate [sigma_ref]");
      sigma_start_ = keyword_number(error, "fix wall/servo", "ramp", arg[iarg + 1], "sigma_start (Pa)");
      sigma_max_ = keyword_number(error, "fix wall/servo", "ramp", arg[iarg + 2], "sigma_max (Pa)");
      load_rate_ = keyword_number(error, "fix wall/servo", "ramp", arg[iarg + 3], "the load rate L_R");
      iarg += 4;
      if (iarg < narg && isdigit(arg[iarg][0]))
        sigma_ref_ = keyword_number(error, "fix wall/servo", "ramp", arg[iarg++], "sigma_ref (Pa)");
      expect(error, sigma_start_ > 0.0 && sigma_max_ >= sigma_start_,
             "keyword 'ramp' expects 0 < sigma_start <= sigma_max (Pa)");
      try {
        crush::LoadRamp(load_rate_, sigma_ref_).steps_to_reach(sigma_start_, sigma_start_);
      } catch (const crush::ModelError &e) {
        expect(error, false, std::string("keyword 'ramp': ") + e.what());
      }
    } else if (key == "alpha") {
      expect(error, iarg + 1 < narg, "keyword 'alpha' expects a value in (0, 1]");
      alpha_ = keyword_number(error, "fix wall/servo", key, arg[iarg + 1], "a value in (0, 1]");
      expect(error, alpha_ > 0.0 && alpha_ <= 1.0, "keyword 'alpha' expects a value in (0, 1]");
      iarg += 2;
    } else if (key == "max_step") {
      expect(error, iarg + 1 < narg, "keyword 'max_step' expects a length > 0 (m)");
      max_step_ = keyword_number(error, "fix wall/servo", key, arg[iarg + 1], "a length > 0 (m)");
      expect(error, max_step_ > 0.0, "keyword 'max_step' expects a length > 0 (m)");
      iarg += 2;
    } else if (key == "progress") {
      expect(error, iarg + 1 < narg, "keyword 'progress' expects a percentage in (0, 100]");
      progress_percent_ = keyword_number(error, "fix wall/servo", key, arg[iarg + 1], "a percentage in (0, 100]");
      expect(error, progress_percent_ > 0.0 && progress_percent_ <= 100.0,
             "keyword 'progress' expects a percentage in (0, 100]");
      iarg += 2;
    } else {
      expect(error, false, "unknown keyword '" + key + "' (expected type, x, y, z, ramp, alpha, max_step or progress)");
    }
  }
  expect(error, wall_type_ > 0, "keyword 'type' (the walls' atom type, for their material) is required");
  for (int a = 0; a < 3; a++)
    expect(error, mode_[a] != RAMP || load_rate_ > 0.0,
           std::string("axis ") + kAxis[a] + " is 'ramp' but no 'ramp sigma_start sigma_max load_rate' is given");
  target_ = sigma_start_;
  ramp_steps_ = load_rate_ > 0.0 ? crush::LoadRamp(load_rate_, sigma_ref_).steps_to_reach(sigma_start_, sigma_max_) : 0;

  vector_flag = 1;
  size_vector = 18;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

FixWallServo::~FixWallServo()
{
}

void FixWallServo::parse_mode(int axis, int narg, char **arg, int &iarg)
{
  const std::string name(1, kAxis[axis]);
  expect(error, iarg + 1 < narg, "keyword '" + name + "' expects fixed, ramp, stress S or velocity V");
  const std::string mode = arg[iarg + 1];
  if (mode == "fixed") {
    mode_[axis] = FIXED;
    iarg += 2;
  } else if (mode == "ramp") {
    mode_[axis] = RAMP;
    iarg += 2;
  } else if (mode == "stress" || mode == "velocity") {
    expect(error, iarg + 2 < narg, "keyword '" + name + " " + mode + "' expects a value");
    mode_[axis] = mode == "stress" ? STRESS : VELOCITY;
    value_[axis] = keyword_number(error, "fix wall/servo", name + " " + mode, arg[iarg + 2],
                                  mode == "stress" ? "a stress > 0 (Pa)" : "a velocity (m/s)");
    expect(error, mode == "velocity" || value_[axis] > 0.0, "keyword '" + name + " stress' expects a stress > 0 (Pa)");
    iarg += 3;
  } else {
    expect(error, false, "keyword '" + name + "' expects fixed, ramp, stress S or velocity V, got '" + mode + "'");
  }
}

int FixWallServo::setmask()
{
  return POST_FORCE;
}

// The eq. 8 factor of each particle type against the wall type, from youngsModulus/poissonsRatio.
void FixWallServo::init()
{
  const int ntypes = atom->ntypes;
  try {
    wall_coefficients_.resize(ntypes + 1);
    for (int t = 1; t <= ntypes; t++)
      wall_coefficients_[t] = crush::hertz_mindlin_coefficients(type_shear_material(modify, ntypes, t, style),
                                                                type_shear_material(modify, ntypes, wall_type_, style));
  } catch (const crush::ModelError &e) {
    error->all(FLERR, (std::string("fix wall/servo: youngsModulus/poissonsRatio: ") + e.what()).c_str());
  }
  if (max_step_ == 0.0) {
    double rmin = 1e300, rmin_all = 0.0;
    for (int i = 0; i < atom->nlocal; i++) rmin = std::min(rmin, atom->radius[i]);
    MPI_Allreduce(&rmin, &rmin_all, 1, MPI_DOUBLE, MPI_MIN, world);
    max_step_ = rmin_all < 1e300 ? 1e-3 * rmin_all : 1e-9;
  }
}

void FixWallServo::setup(int)
{
  double force[6], stiffness[3];
  apply_contacts(force, stiffness);
  for (int k = 0; k < 6; k++) force_[k] = force[k];
}

void FixWallServo::post_force(int)
{
  double force[6], stiffness[3];
  apply_contacts(force, stiffness);
  double force_before[6];
  for (int k = 0; k < 6; k++) {
    force_before[k] = force_[k];
    force_[k] = force[k];
  }
  move_walls(force, force_before, stiffness);
}

// Hertz contacts of the local particles with the six walls: adds the forces, returns the total
// compressive force on each wall and the contact stiffness dF/dU = 1.5 k_N of each hi wall.
void FixWallServo::apply_contacts(double *force, double *stiffness)
{
  double local[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  double **x = atom->x, **f = atom->f;
  const double *radius = atom->radius;
  const int *mask = atom->mask, *type = atom->type;
  const ContactLoadRecorder *recorder = monitor_.recorder();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double r = radius[i];
    for (int a = 0; a < 3; a++)
      for (int side = 0; side < 2; side++) {
        const double U = overlap(x[i], r, a, side);
        if (U <= 0.0) continue;
        const double kn = secant_stiffness(type[i], r, U);
        const double Fn = kn * U;
        f[i][a] += side == 0 ? Fn : -Fn;
        local[2 * a + side] += Fn;
        if (side == 1) local[6 + a] += 1.5 * kn;
        if (recorder) recorder->record(i, -1, true, type[i], wall_type_, Fn, r);
      }
  }
  double all[9];
  MPI_Allreduce(local, all, 9, MPI_DOUBLE, MPI_SUM, world);
  for (int k = 0; k < 6; k++) force[k] = all[k];
  for (int a = 0; a < 3; a++) stiffness[a] = all[6 + a];
}

void FixWallServo::add_contact_stiffness(std::vector<crush::ContactStiffness> &stiffness) const
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *mask = atom->mask, *type = atom->type;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int a = 0; a < 3; a++)
      for (int side = 0; side < 2; side++) {
        const double U = overlap(x[i], radius[i], a, side);
        if (U > 0.0) stiffness[i].translational += crush::tangent_normal_stiffness(secant_stiffness(type[i], radius[i], U));
      }
  }
}

// Every processor makes the same move from the same reduced numbers.
void FixWallServo::move_walls(const double *force, const double *force_before, const double *stiffness)
{
  const double before = target_;
  if (load_rate_ > 0.0 && target_ < sigma_max_) {
    target_ = std::min(sigma_max_, crush::LoadRamp(load_rate_, sigma_ref_).next(target_));
    if (!ramp_started_) {
      ramp_started_ = true;
      ramp_wall_start_ = MPI_Wtime();
      ramp_started_steps_ = ramp_done_;
      next_report_ = ramp_done_ + progress_percent_ * 0.01 * ramp_steps_;
    }
    ramp_done_ += 1.0;
    if (progress_percent_ > 0.0 && (ramp_done_ >= next_report_ || target_ >= sigma_max_)) {
      report_progress();
      next_report_ += progress_percent_ * 0.01 * ramp_steps_;
    }
  }
  for (int a = 0; a < 3; a++) {
    double &hi = wall_[2 * a + 1];
    if (mode_[a] == VELOCITY) {
      hi += value_[a] * update->dt;
    } else if (mode_[a] == RAMP || mode_[a] == STRESS) {
      const double sigma = mode_[a] == RAMP ? target_ : value_[a];
      double increment = 0.0, sample_stiffness = 0.0;
      if (mode_[a] == RAMP) {
        increment = (target_ - before) * area(a);
        sample_stiffness_[a].add(force[2 * a + 1] - force_before[2 * a + 1], last_move_[a]);
        sample_stiffness = sample_stiffness_[a].value(stiffness[a]);
      }
      last_move_[a] = crush::servo_step(force[2 * a + 1], sigma * area(a), stiffness[a], alpha_, max_step_,
                                        increment, sample_stiffness);
      // A constant stress on a dilating or creeping sample: the wall's average motion, fed forward.
      // Only while the wall has contacts (an approach at max_step is not a drift), within max_step.
      if (mode_[a] == STRESS && stiffness[a] > 0.0) {
        last_move_[a] = std::max(-max_step_, std::min(max_step_, last_move_[a] + drift_[a].value()));
        drift_[a].add(last_move_[a]);
      } else if (mode_[a] == STRESS) {
        drift_[a] = crush::DriftEstimate();
      }
      hi -= last_move_[a];
    }
  }
}

// One line: ramp stage, target and measured stresses, particles, crushing events (of a fix crush, if
// any) and the wall-clock time left, extrapolated from this run's rate so far.
void FixWallServo::report_progress()
{
  if (comm->me != 0) return;
  const double done = ramp_done_ / std::max(1.0, ramp_steps_);
  const double elapsed = MPI_Wtime() - ramp_wall_start_;
  const double left = elapsed * std::max(0.0, ramp_steps_ - ramp_done_) / std::max(1.0, ramp_done_ - ramp_started_steps_);
  Fix *crush = modify->find_fix_style_strict("crush", 0);
  char events[64] = "";
  if (crush) snprintf(events, sizeof(events), ", %.0f events", crush->compute_vector(0));
  char line[512];
  snprintf(line, sizeof(line),
           "wall/servo: ramp %5.1f%%  target %.4g MPa  sigma x y z %.4g %.4g %.4g MPa  %.0f particles%s  "
           "elapsed %.0f s  left %.0f s\n",
           100.0 * done, target_ * 1e-6, stress(0) * 1e-6, stress(1) * 1e-6, stress(2) * 1e-6,
           static_cast<double>(atom->natoms), events, elapsed, left);
  if (screen) fputs(line, screen);
  if (logfile) fputs(line, logfile);
}

double FixWallServo::area(int axis) const
{
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  return (wall_[2 * b + 1] - wall_[2 * b]) * (wall_[2 * c + 1] - wall_[2 * c]);
}

// Mean compressive stress of the two walls of an axis (Pa).
double FixWallServo::stress(int axis) const
{
  return 0.5 * (force_[2 * axis] + force_[2 * axis + 1]) / area(axis);
}

// [1-6] wall positions, [7-9] stresses sigma_x, sigma_y, sigma_z, [10] ramp target, [11] volume,
// [12] steps of the whole ramp (eq. 11) from sigma_start to sigma_max, [13-18] the stress on each wall.
double FixWallServo::compute_vector(int n)
{
  if (n >= 12) return force_[n - 12] / area((n - 12) / 2);
  if (n < 6) return wall_[n];
  if (n < 9) return stress(n - 6);
  if (n == 9) return target_;
  if (n == 11) return ramp_steps_;
  return (wall_[1] - wall_[0]) * (wall_[3] - wall_[2]) * (wall_[5] - wall_[4]);
}

void FixWallServo::write_restart(FILE *fp)
{
  double list[7] = {wall_[0], wall_[1], wall_[2], wall_[3], wall_[4], wall_[5], target_};
  if (comm->me == 0) {
    int size = 7 * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 7, fp);
  }
}

void FixWallServo::restart(char *buf)
{
  const double *list = reinterpret_cast<const double *>(buf);
  for (int k = 0; k < 6; k++) wall_[k] = list[k];
  target_ = list[6];
  if (load_rate_ > 0.0)
    ramp_done_ = static_cast<double>(crush::LoadRamp(load_rate_, sigma_ref_).steps_to_reach(sigma_start_, target_));
}

/* ----------------------------------------------------------------------
   liggghts-crush: fix wall/servo (see fix_wall_servo.h).
------------------------------------------------------------------------- */
#include "fix_wall_servo.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "crush_load_ramp.h"
#include "crush_model_error.h"
#include "crush_number.h"
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
const double kMaxStress = 1e12;  // Pa: ten times the strength of the strongest solids
}  // namespace

FixWallServo::FixWallServo(LAMMPS *lmp, int narg, char **arg) :
  Fix(lmp, narg, arg), wall_type_(0), sigma_start_(1e3), sigma_max_(0.0), load_rate_(0.0), sigma_ref_(1e3),
  target_(0.0), alpha_(0.5), max_step_(0.0), progress_percent_(0.0), ramp_done_(0.0),
  next_report_(0.0), ramp_wall_start_(0.0), ramp_started_steps_(0.0), ramp_started_(false), monitor_(lmp)
{
  for (int a = 0; a < 3; a++) {
    mode_[a] = FIXED;
    value_[a] = 0.0;
    force_[2 * a] = force_[2 * a + 1] = 0.0;
    last_move_[a] = 0.0;
  }
  fix_input(this, error, [&] { parse_arguments(words(narg, arg)); });
  warn_suspicious();
  target_ = sigma_start_;
  ramp_steps_ = load_rate_ > 0.0 ? crush::LoadRamp(load_rate_, sigma_ref_).steps_to_reach(sigma_start_, sigma_max_) : 0;

  vector_flag = 1;
  size_vector = 20;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

FixWallServo::~FixWallServo()
{
}

// xlo xhi ylo yhi zlo zhi, then the keyword table; throws crush::ModelError naming the keyword.
void FixWallServo::parse_arguments(const std::vector<std::string> &args)
{
  const char *const wall_names[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
  if (args.size() < 9)
    throw crush::ModelError("expected 'fix ID group wall/servo xlo xhi ylo yhi zlo zhi type T x MODE y MODE z MODE'");
  for (int k = 0; k < 6; k++)
    if (!crush::parse_finite(args[3 + k], wall_[k]))
      throw crush::ModelError(std::string("wall ") + wall_names[k] + " expects a position (m), got '" + args[3 + k] + "'");
  for (int a = 0; a < 3; a++)
    if (!(wall_[2 * a + 1] > wall_[2 * a]))
      throw crush::ModelError(std::string("the ") + kAxis[a] + "hi wall must lie above the " + kAxis[a] + "lo wall");

  crush::KeywordTable t;
  t.add("type", "the walls' atom type 1..ntypes (for their material)",
        [this, &t](const std::vector<std::string> &w, std::size_t at) {
    const double v = t.value("type", w, at + 1);
    if (!(v >= 1.0 && v <= atom->ntypes && v == std::floor(v))) t.fail("type", w[at + 1]);
    wall_type_ = static_cast<int>(v);
    return std::size_t(1);
  }, true);
  for (int a = 0; a < 3; a++) t.add(std::string(1, kAxis[a]), "fixed, ramp, stress S (Pa, in (0, 1e12]), velocity V "
                                   "(m/s, |V| <= 1000) or mean P (Pa, in (0, 1e12])",
                                   [this, &t, a](const std::vector<std::string> &w, std::size_t at) {
    return read_mode(t, a, w, at);
  });
  t.add("ramp", "sigma_start sigma_max load_rate [sigma_ref] (Pa, 0 < sigma_start <= sigma_max <= 1e12; "
               "load_rate in (0, 100])",
        [this, &t](const std::vector<std::string> &w, std::size_t at) {
    sigma_start_ = t.value("ramp", w, at + 1);
    sigma_max_ = t.value("ramp", w, at + 2);
    load_rate_ = t.value("ramp", w, at + 3);
    std::size_t read = 3;
    if (at + 4 < w.size() && !t.is_keyword(w[at + 4])) sigma_ref_ = t.value("ramp", w, at + ++read);
    if (!(sigma_start_ > 0.0 && sigma_max_ >= sigma_start_ && sigma_max_ <= kMaxStress)) t.fail("ramp", w[at + 1] + " " + w[at + 2]);
    if (!(load_rate_ > 0.0 && load_rate_ <= 100.0)) t.fail("ramp", w[at + 3]);
    crush::LoadRamp(load_rate_, sigma_ref_).steps_to_reach(sigma_start_, sigma_start_);  // checks L_R, sigma_ref
    return read;
  });
  t.ascending("outputs", "ascending stresses > 0 (Pa)", outputs_);
  t.number("alpha", "a value in (0, 1]", crush::open_closed(0.0, 1.0), alpha_)
   .number("max_step", "a length in (0, 1] m", crush::open_closed(0.0, 1.0), max_step_)
   .number("progress", "a percentage in (0, 100]", crush::open_closed(0.0, 100.0), progress_percent_);
  t.parse(args, 9);

  if (!outputs_.empty() && !(load_rate_ > 0.0))
    throw crush::ModelError("keyword 'outputs' needs 'ramp sigma_start sigma_max load_rate'");
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < a; b++)
      if (mode_[a] == MEAN && mode_[b] == MEAN && value_[a] != value_[b])
        throw crush::ModelError(std::string("axes ") + kAxis[b] + " and " + kAxis[a] +
                                " hold different mean stresses: the axes in mode 'mean' share one P");
  for (int a = 0; a < 3; a++)
    if (mode_[a] == RAMP && !(load_rate_ > 0.0))
      throw crush::ModelError(std::string("axis ") + kAxis[a] +
                              " is 'ramp' but no 'ramp sigma_start sigma_max load_rate' is given");
}

// Legal values that are unlikely to be meant.
void FixWallServo::warn_suspicious()
{
  if (load_rate_ > 1.0)
    fix_warning(this, error, comm->me, "ramp load_rate above 1: the stress grows by more than sigma_ref per step, "
                                       "too fast for a quasi-static test (the paper's L_R is 0.05 to 0.1)");
  for (int a = 0; a < 3; a++) {
    if (((mode_[a] == STRESS || mode_[a] == MEAN) && value_[a] > 1e10) || (mode_[a] == RAMP && sigma_max_ > 1e10))
      fix_warning(this, error, comm->me, std::string("axis ") + kAxis[a] + ": a stress above 10 GPa, beyond the "
                                                                           "crushing of any sand");
    if (mode_[a] == VELOCITY && std::fabs(value_[a]) > 10.0)
      fix_warning(this, error, comm->me, std::string("axis ") + kAxis[a] + ": a wall faster than 10 m/s is an impact, "
                                                                           "not a quasi-static test");
  }
}

// x|y|z fixed | ramp | stress S | velocity V | mean P
std::size_t FixWallServo::read_mode(const crush::KeywordTable &t, int axis, const std::vector<std::string> &w,
                                    std::size_t at)
{
  const std::string name(1, kAxis[axis]);
  const std::string mode = at + 1 < w.size() ? w[at + 1] : "";
  if (mode == "fixed" || mode == "ramp") {
    mode_[axis] = mode == "fixed" ? FIXED : RAMP;
    return 1;
  }
  if (mode != "stress" && mode != "velocity" && mode != "mean") t.fail(name, mode);
  mode_[axis] = mode == "stress" ? STRESS : (mode == "mean" ? MEAN : VELOCITY);
  value_[axis] = t.value(name, w, at + 2);
  if (mode != "velocity" && !(value_[axis] > 0.0 && value_[axis] <= kMaxStress)) t.fail(name, mode + " " + w[at + 2]);
  if (mode == "velocity" && !(std::fabs(value_[axis]) <= 1000.0)) t.fail(name, mode + " " + w[at + 2]);
  return 2;
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
    error->fix_error(FLERR, this, (std::string("youngsModulus/poissonsRatio: ") + e.what()).c_str());
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
      // a resumed run keeps the uninterrupted run's report points
      if (next_report_ <= ramp_done_) next_report_ = ramp_done_ + progress_percent_ * 0.01 * ramp_steps_;
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
    } else if (mode_[a] != FIXED) {
      const bool held = mode_[a] == STRESS || mode_[a] == MEAN;
      const double sigma = mode_[a] == RAMP ? target_ : (mode_[a] == MEAN ? mean_axis_target(a) : value_[a]);
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
      if (held && stiffness[a] > 0.0) {
        last_move_[a] = std::max(-max_step_, std::min(max_step_, last_move_[a] + drift_[a].value()));
        drift_[a].add(last_move_[a]);
      } else if (held) {
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

// The stress of an axis in mode mean: its share of three times the mean stress, less what the other
// axes carry (their measured stresses, this step's forces).
double FixWallServo::mean_axis_target(int axis) const
{
  double others = 0.0;
  int n_mean = 0;
  for (int b = 0; b < 3; b++) {
    if (mode_[b] == MEAN) n_mean++;
    else others += stress(b);
  }
  return crush::mean_stress_target(value_[axis], others, n_mean);
}

// The ramp's stops: the output stresses up to sigma_max, and sigma_max.
std::vector<double> FixWallServo::ramp_stops() const
{
  std::vector<double> stops;
  for (double s : outputs_)
    if (s < sigma_max_) stops.push_back(s);
  stops.push_back(sigma_max_);
  return stops;
}

// Ramp steps until the target reaches the next stop above it (0: the ramp is done).
double FixWallServo::steps_to_next_stop() const
{
  if (!(load_rate_ > 0.0)) return 0.0;
  for (double s : ramp_stops())
    if (s > target_) return static_cast<double>(crush::LoadRamp(load_rate_, sigma_ref_).steps_to_reach(target_, s));
  return 0.0;
}

// The last stop the target has reached (0: none yet).
double FixWallServo::last_stop() const
{
  double reached = 0.0;
  for (double s : ramp_stops())
    if (load_rate_ > 0.0 && s <= target_) reached = s;
  return reached;
}

// [1-6] wall positions, [7-9] stresses sigma_x, sigma_y, sigma_z, [10] ramp target, [11] volume,
// [12] steps of the whole ramp (eq. 11) from sigma_start to sigma_max, [13-18] the stress on each wall,
// [19] ramp steps to the next stop (output stress or sigma_max), [20] the last stop reached.
double FixWallServo::compute_vector(int n)
{
  if (n == 18) return steps_to_next_stop();
  if (n == 19) return last_stop();
  if (n >= 12) return force_[n - 12] / area((n - 12) / 2);
  if (n < 6) return wall_[n];
  if (n < 9) return stress(n - 6);
  if (n == 9) return target_;
  if (n == 11) return ramp_steps_;
  return (wall_[1] - wall_[0]) * (wall_[3] - wall_[2]) * (wall_[5] - wall_[4]);
}

// Everything the servo carries from step to step, so that a run resumed from a restart file moves the
// walls as the uninterrupted one (the forces themselves are recomputed at setup). Versioned: a file
// of another layout is refused by name.
namespace {
const int kRestartVersion = 2;
struct RestartState {
  int version;
  int mode[3];
  double value[3], ramp[4], alpha;  // the settings: ramp = sigma_start, sigma_max, load_rate, sigma_ref
  double wall[6], target, ramp_done, next_report, max_step, last_move[3];
  crush::StiffnessEstimate sample_stiffness[3];
  crush::DriftEstimate drift[3];
};
}  // namespace

void FixWallServo::write_restart(FILE *fp)
{
  RestartState state;
  state.version = kRestartVersion;
  settings_state(state.mode, state.value, state.ramp, state.alpha);
  for (int k = 0; k < 6; k++) state.wall[k] = wall_[k];
  state.target = target_;
  state.ramp_done = ramp_done_;
  state.next_report = next_report_;
  state.max_step = max_step_;
  for (int a = 0; a < 3; a++) {
    state.last_move[a] = last_move_[a];
    state.sample_stiffness[a] = sample_stiffness_[a];
    state.drift[a] = drift_[a];
  }
  if (comm->me == 0) {
    int size = sizeof(RestartState);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(&state, sizeof(RestartState), 1, fp);
  }
}

void FixWallServo::restart(char *buf)
{
  int version = 0;
  std::memcpy(&version, buf, sizeof(int));
  if (version != kRestartVersion) {
    char msg[256];
    snprintf(msg, sizeof(msg), "the restart file's fix wall/servo section is version %d; this build reads version %d "
             "(a file written before the sections had versions holds only the wall positions)", version, kRestartVersion);
    error->fix_error(FLERR, this, msg);
  }
  RestartState state;
  std::memcpy(&state, buf, sizeof(RestartState));
  for (int k = 0; k < 6; k++) wall_[k] = state.wall[k];
  target_ = state.target;
  // The same settings: this fix continues the one that wrote the file (a checkpoint). Other settings
  // (a deck that prepared a sample at one stress and loads it another way): the walls' positions and
  // the stress reached carry over, the servo starts afresh.
  int mode[3];
  double value[3], ramp[4], alpha;
  settings_state(mode, value, ramp, alpha);
  const bool same = std::memcmp(mode, state.mode, sizeof(mode)) == 0 && std::memcmp(value, state.value, sizeof(value)) == 0 &&
                    std::memcmp(ramp, state.ramp, sizeof(ramp)) == 0 && alpha == state.alpha;
  if (!same) {
    if (load_rate_ > 0.0)
      ramp_done_ = static_cast<double>(crush::LoadRamp(load_rate_, sigma_ref_).steps_to_reach(sigma_start_, target_));
    return;
  }
  ramp_done_ = state.ramp_done;
  next_report_ = state.next_report;
  max_step_ = state.max_step;
  for (int a = 0; a < 3; a++) {
    last_move_[a] = state.last_move[a];
    sample_stiffness_[a] = state.sample_stiffness[a];
    drift_[a] = state.drift[a];
  }
}

void FixWallServo::settings_state(int *mode, double *value, double *ramp, double &alpha) const
{
  for (int a = 0; a < 3; a++) {
    mode[a] = static_cast<int>(mode_[a]);
    value[a] = value_[a];
  }
  ramp[0] = sigma_start_;
  ramp[1] = sigma_max_;
  ramp[2] = load_rate_;
  ramp[3] = sigma_ref_;
  alpha = alpha_;
}

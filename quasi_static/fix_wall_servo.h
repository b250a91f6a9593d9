/* ----------------------------------------------------------------------
   liggghts-crush: fix wall/servo, six smooth planar walls around a cuboid sample, each axis fixed,
   stress-controlled (constant, the load ramp of eq. 11, or sharing a constant mean stress with the
   other axes) or moved at a constant velocity (strain control). See doc/fix_wall_servo.txt.

   fix ID group wall/servo xlo xhi ylo yhi zlo zhi type T x MODE y MODE z MODE keyword value ...
     MODE = fixed | ramp | stress S | velocity V | mean P
     ramp sigma_start sigma_max load_rate [sigma_ref]    (eq. 11, natural log, default 1 kPa)
     alpha a (servo relaxation, default 0.5)   max_step d (m per step, default 1e-3 r_min)
     progress P (a line on the screen every P percent of the ramp's steps, with the time left)
     outputs s1 s2 ... (Pa: stresses where a deck wants outputs; f_walls[19] gives the ramp steps to
       the next of them or sigma_max, f_walls[20] the last one reached, so 'run $(f_walls[19])' stops there)

   Contacts: the hertz/scaled normal law (eq. 8) with the wall type's material, no friction (smooth
   walls); they feed a fix crush like pair contacts. The hi wall of a controlled axis moves; the lo
   wall stays. The servo is PFC's, with the gain scaled by the wall's contact stiffness
   (servo_wall_law.h).
------------------------------------------------------------------------- */
#ifdef FIX_CLASS

FixStyle(wall/servo,FixWallServo)

#else

#ifndef LMP_FIX_WALL_SERVO_H
#define LMP_FIX_WALL_SERVO_H

#include <cmath>
#include <string>
#include <vector>

#include "critical_step_law.h"
#include "crush_keywords.h"
#include "servo_wall_law.h"
#include "fix.h"
#include "contact_load_monitor.h"

namespace LAMMPS_NS {

class FixWallServo : public Fix {
 public:
  FixWallServo(class LAMMPS *, int, char **);
  ~FixWallServo();
  int setmask();
  void init();
  void setup(int);
  void post_force(int);
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);
  // Adds the tangent stiffness of each local particle's wall contacts (smooth: normal only), for
  // fix dt/stiffness.
  void add_contact_stiffness(std::vector<crush::ContactStiffness> &stiffness) const;

 private:
  enum Mode { FIXED, RAMP, STRESS, VELOCITY, MEAN };

  void parse_arguments(const std::vector<std::string> &args);
  void warn_suspicious();
  std::size_t read_mode(const crush::KeywordTable &t, int axis, const std::vector<std::string> &w, std::size_t at);
  void apply_contacts(double *force, double *stiffness);
  void move_walls(const double *force, const double *force_before, const double *stiffness);
  // Overlap (m; <= 0: no contact) of a particle at x of radius r with the lo (side 0) or hi (side 1)
  // wall of axis a.
  double overlap(const double *x, double r, int a, int side) const
  {
    return r - (side == 0 ? x[a] - wall_[2 * a] : wall_[2 * a + 1] - x[a]);
  }
  // eq. 8 with the wall convention D1 D2/(D1+D2) -> D = 2r: the secant k_N (N/m) at overlap U.
  double secant_stiffness(int type, double r, double U) const
  {
    return crush::contact_stiffness(wall_coefficients_[type], 2.0 * r, U).normal;
  }
  std::vector<double> ramp_stops() const;
  double steps_to_next_stop() const;
  double last_stop() const;
  double area(int axis) const;
  double stress(int axis) const;
  double mean_axis_target(int axis) const;
  void report_progress();
  // The settings a restart section must match for the servo's state to carry over.
  void settings_state(int *mode, double *value, double *ramp, double &alpha) const;

  double wall_[6];        // positions (m): xlo xhi ylo yhi zlo zhi
  Mode mode_[3];
  double value_[3];       // constant stress or mean stress (Pa), or velocity (m/s), of each axis
  int wall_type_;
  double sigma_start_, sigma_max_, load_rate_, sigma_ref_, target_;
  double ramp_steps_;
  std::vector<double> outputs_;  // output stresses (Pa) at which the ramp stops (outputs keyword)
  double alpha_, max_step_;
  double force_[6];       // compressive force on each wall (N), last step
  crush::StiffnessEstimate sample_stiffness_[3];  // dF/dx of each ramp axis' hi wall
  crush::DriftEstimate drift_[3];                 // average step of each stress axis' hi wall
  double last_move_[3];   // the hi wall's last displacement towards the sample (m)
  std::vector<crush::HertzMindlinCoefficients> wall_coefficients_;  // per particle type, against the wall type
  double progress_percent_;  // 0: no progress lines
  double ramp_done_;         // ramp steps taken
  double next_report_;       // ramp steps at the next progress line
  double ramp_wall_start_;   // MPI_Wtime() at the first ramp step of this run
  double ramp_started_steps_;  // ramp steps taken before it (a restarted run)
  bool ramp_started_;
  ContactLoadMonitor monitor_;
};

}  // namespace LAMMPS_NS

#endif
#endif

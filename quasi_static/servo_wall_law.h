/* Stress-controlled walls (plain C++): PFC's servo for a rigid planar wall, with the gain scaled by
   the current stiffness of the wall's contacts (Itasca PFC3D manual, "servo-control").

   Each step the wall moves towards the sample by
     dx = [alpha (F_target - F_wall) + dF_target] / k_wall,     |dx| <= max_step
   where k_wall is the sum of the tangent normal stiffnesses dF/dU of the wall's contacts (for Hertz,
   1.5 k_N). With alpha < 1 this is a damped Newton step on the wall force: the gain follows the Hertz
   stiffness, which grows by two orders of magnitude between 1 kPa and 100 MPa, so the servo is
   neither sluggish at the start nor unstable at the end. Without contacts the wall advances by
   max_step. dF_target, the target's increase over the step (the load ramp), is fed forward: without
   it the wall lags a ramp by dF_target / alpha. The feed-forward divides by the stiffness of the
   whole sample as the wall sees it, dF/dx over the recent steps (StiffnessEstimate): k_wall is the
   stiffness of the wall's own contacts only, many times the sample's (the grains behind them yield
   too), and a ramp fed forward with k_wall still lags by dF_target (k_wall/K_sample - 1) / alpha.
   SI units: N, N/m, m. */
#ifndef SERVO_WALL_LAW_H
#define SERVO_WALL_LAW_H

namespace crush {

// Displacement of the wall towards the sample in one step (m; negative: away from it). The increment
// is fed forward through sample_stiffness (default: the wall contacts' stiffness).
inline double servo_step(double wall_force, double target_force, double wall_stiffness, double alpha,
                         double max_step, double target_increment = 0.0, double sample_stiffness = 0.0)
{
  if (!(sample_stiffness > 0.0)) sample_stiffness = wall_stiffness;
  double dx = wall_stiffness > 0.0
                  ? alpha * (target_force - wall_force) / wall_stiffness + target_increment / sample_stiffness
                  : max_step;
  if (dx > max_step) dx = max_step;
  if (dx < -max_step) dx = -max_step;
  return dx;
}

// The stress each of n_mean axes held at a mean stress P must carry, so that the three axes' mean is P
// when the others carry other_axes_stress in sum (Pa): a drained test at constant p' (the axial axis
// strain-controlled, the lateral ones sharing 3P - sigma_axial). Never tensile: smooth walls only push.
inline double mean_stress_target(double mean_stress, double other_axes_stress, int n_mean)
{
  const double sigma = (3.0 * mean_stress - other_axes_stress) / n_mean;
  return sigma > 0.0 ? sigma : 0.0;
}

// The sample's stiffness seen by the wall: the ratio of exponential averages of the wall force's
// change and of the wall's displacement per step (weight w per step: a memory of about 1/w steps).
// Until the wall has advanced and the force grown on average, and never outside
// [1e-3 k_wall, k_wall], it falls back to the bounds.
class StiffnessEstimate {
 public:
  explicit StiffnessEstimate(double weight = 0.01) : weight_(weight), force_change_(0.0), displacement_(0.0) {}
  void add(double force_change, double displacement)
  {
    force_change_ += weight_ * (force_change - force_change_);
    displacement_ += weight_ * (displacement - displacement_);
  }
  double value(double wall_stiffness) const
  {
    if (!(displacement_ > 0.0 && force_change_ > 0.0)) return wall_stiffness;
    const double k = force_change_ / displacement_;
    return k < 1e-3 * wall_stiffness ? 1e-3 * wall_stiffness : (k > wall_stiffness ? wall_stiffness : k);
  }

 private:
  double weight_, force_change_, displacement_;
};

// The average of a wall's recent displacements per step (exponential, weight w per step). A wall
// held at a constant stress on a sample that dilates or creeps must keep moving; fed back alone it
// lags by its speed x k_wall / alpha. Adding this average to the step makes the servo
// proportional-integral (the average integrates the error with gain w alpha / k_wall): no lag.
class DriftEstimate {
 public:
  explicit DriftEstimate(double weight = 0.01) : weight_(weight), drift_(0.0) {}
  void add(double displacement) { drift_ += weight_ * (displacement - drift_); }
  double value() const { return drift_; }

 private:
  double weight_, drift_;
};

}  // namespace crush

#endif

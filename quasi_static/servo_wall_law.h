/* Stress-controlled walls (plain C++): PFC's servo for a rigid planar wall, with the gain scaled by
   the current stiffness of the wall's contacts (Itasca PFC3D manual, "servo-control").

   Each step the wall moves towards the sample by
     dx = [alpha (F_target - F_wall) + dF_target] / k_wall,     |dx| <= max_step
   where k_wall is the sum of the tangent normal stiffnesses dF/dU of the wall's contacts (for Hertz,
   1.5 k_N). With alpha < 1 this is a damped Newton step on the wall force: the gain follows the Hertz
   stiffness, which grows by two orders of magnitude between 1 kPa and 100 MPa, so the servo is
   neither sluggish at the start nor unstable at the end. Without contacts the wall advances by
   max_step. dF_target, the target's increase over the step (the load ramp), is fed forward: without
   it the wall lags a ramp by dF_target / alpha. SI units: N, N/m, m. */
#ifndef SERVO_WALL_LAW_H
#define SERVO_WALL_LAW_H

namespace crush {

// Displacement of the wall towards the sample in one step (m; negative: away from it).
inline double servo_step(double wall_force, double target_force, double wall_stiffness, double alpha,
                         double max_step, double target_increment = 0.0)
{
  double dx = wall_stiffness > 0.0
                  ? (alpha * (target_force - wall_force) + target_increment) / wall_stiffness
                  : max_step;
  if (dx > max_step) dx = max_step;
  if (dx < -max_step) dx = -max_step;
  return dx;
}

}  // namespace crush

#endif

/* Local damping (plain C++): PFC's "local" non-viscous damping, used by Ciantia et al. (2014) for
   quasi-static runs (alpha = 0.05, Table 2).

     F_d = -alpha |F| sign(v)     per Cartesian component, and likewise M_d = -alpha |M| sign(omega)

   F is the total unbalanced force (moment) on the particle, v (omega) its velocity (angular velocity);
   sign(0) = 0. It removes a fraction alpha of the force's power when the force drives the motion and
   adds it when it opposes it, independent of the particle's mass and of the time step (Cundall 1987,
   "Distinct element models of rock and soil structure"; Itasca PFC3D manual). */
#ifndef LOCAL_DAMPING_LAW_H
#define LOCAL_DAMPING_LAW_H

namespace crush {

// The damped value of one component of a force (N) or moment (N m) acting on a body moving with
// velocity v (m/s) or angular velocity omega (rad/s) in that component.
// Branch-free, as the sign of a velocity component is unpredictable (its gain was not measured on
// its own); x - s y with s = +-1 is exactly x -+ y, so the result is PFC's rule to the bit.
inline double locally_damped(double force, double velocity, double alpha)
{
  const double magnitude = force < 0.0 ? -force : force;
  const double sign = static_cast<double>((velocity > 0.0) - (velocity < 0.0));
  return force - sign * (alpha * magnitude);
}

}  // namespace crush

#endif

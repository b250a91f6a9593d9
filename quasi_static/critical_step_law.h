/* Critical time step from the contact stiffness (plain C++): PFC's automatic time step for
   Hertz-Mindlin contacts (Itasca PFC3D manual, "time step determination").

   A particle of mass m and radius r held by contacts of tangent normal stiffness k_n and tangent
   shear stiffness k_s oscillates no faster than
     translation: sqrt(m / sum(k_n + k_s)),   rotation: sqrt(I / sum(k_s r^2)) = sqrt(0.4 m / sum k_s)
   and central differences are stable below that period scale. For eq. 8-9, k_n = 1.5 k_N (the
   tangent of F = k_N U with k_N ~ sqrt(U)) and k_s = k_S. Hertz contacts soften at small overlaps, so
   at low stress the step is several times the Rayleigh step that a fixed time step must respect, and
   a load ramp counted in steps (eq. 11) is then slower in physical time, as it was in PFC. */
#ifndef CRITICAL_STEP_LAW_H
#define CRITICAL_STEP_LAW_H

#include <algorithm>
#include <cmath>

#include "hertz_mindlin_stiffness_sum.h"

namespace crush {

// The particle's critical step (s); 1e300 without contacts.
inline double critical_step(double mass, const ContactStiffness &sum)
{
  double dt = 1e300;
  if (sum.translational > 0.0) dt = std::sqrt(mass / sum.translational);
  if (sum.shear > 0.0) dt = std::min(dt, std::sqrt(0.4 * mass / sum.shear));
  return dt;
}

// The next time step: fraction of the smallest critical step, growing by at most 'growth' per update
// (a step that shrinks does so at once), never above dt_max.
inline double next_time_step(double current, double smallest_critical, double fraction, double growth,
                             double dt_max)
{
  double dt = fraction * smallest_critical;
  dt = std::min(dt, current * growth);
  return std::min(dt, dt_max);
}

}  // namespace crush

#endif

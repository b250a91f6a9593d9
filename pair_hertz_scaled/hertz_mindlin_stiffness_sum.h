/* The summed contact stiffness of one particle (plain C++): what PFC's automatic time step needs from
   the scaled Hertz-Mindlin law of eq. 8-9 (Ciantia et al. 2014), per contact

     k_n = dF_n/dU = 1.5 k_N   (tangent normal stiffness),   k_s = k_S,

   summed over the particle's contacts. The contact model adds each contact during the force pass
   (contact_stiffness_monitor.h); the critical step is quasi_static/critical_step_law.h. N/m. */
#ifndef HERTZ_MINDLIN_STIFFNESS_SUM_H
#define HERTZ_MINDLIN_STIFFNESS_SUM_H

#include "hertz_mindlin_scaled_law.h"

namespace crush {

// The summed tangent stiffnesses (N/m) of one particle's contacts.
struct ContactStiffness {
  double translational = 0.0;  // sum(k_n + k_s)
  double shear = 0.0;          // sum(k_s)
};

// Adds one contact of stiffness k (eq. 8-9 at its overlap).
inline void add_contact(ContactStiffness &sum, const HertzMindlinStiffness &k)
{
  sum.translational += tangent_normal_stiffness(k.normal) + k.shear;
  sum.shear += k.shear;
}

// Adds one contact of diameter term Dt = D1 D2/(D1+D2) (m) at overlap U (m).
inline void add_contact(ContactStiffness &sum, const HertzMindlinCoefficients &c, double diameter_term,
                        double overlap)
{
  add_contact(sum, contact_stiffness(c, diameter_term, overlap));
}

}  // namespace crush

#endif

/* Crushing model (plain C++): the breakage limit of Ciantia et al. (2014), eq. 2-7 and 10.

   A particle i breaks when the normal force F of one of its contacts reaches
     F_lim = [sigma_lim pi (3 r'/(4 E'))^(2/3)]^3                                  (eq. 5)
   i.e. when the Hertzian contact area pi r_H^2, r_H = (3 F r'/(4 E'))^(1/3) (eq. 2), times sigma_lim
   equals F. r' (eq. 3) and E' (eq. 4) are the contact's effective radius and modulus. A plane wall is
   a sphere of infinite radius made of the wall's material: r' = r_i, E' from eq. 4.
   sigma_lim carries the size effect (eq. 6) with the upscaling factor N (eq. 10):
     sigma_lim = s (d/(N d0))^(-3/m)
   where s is the particle's own strength draw (crush_strength.h). SI units throughout. */
#ifndef CRUSH_BREAKAGE_LIMIT_H
#define CRUSH_BREAKAGE_LIMIT_H

#include <cmath>

#include "crush_constants.h"
#include "hertz_mindlin_contact_load.h"

namespace crush {

// eq. 6/10: sigma_lim = s (d/(N d0))^(-3/m) (Pa) for strength draw s (Pa), diameter d (m),
// reference diameter d0 (m), Weibull modulus m and upscaling factor N.
double size_scaled_strength(double s, double d, double d0, double weibull_m, double scale_factor);

// The breakage check of eq. 5/7 as a product of a contact term and a strength term:
//   F / F_lim = F (4 E'/3)^2 / r'^2  x  1 / (pi sigma_lim)^3
// since (3 r'/(4 E'))^(2/3) cubed is (3 r'/(4 E'))^2. The contact models evaluate the first for each
// contact (contact_load(), hertz_mindlin_contact_load.h), fix crush the second once per particle, and
// the running maximum over a particle's contacts needs no division by its strength.

// The strength term (Pa^-3): 1 / (pi sigma_lim)^3; infinite for zero strength (breaks under any
// load; a particle without load then has contact term 0 and stays whole).
inline double strength_term(double sigma_lim)
{
  const double s = pi * sigma_lim;
  return s > 0.0 ? 1.0 / (s * s * s) : HUGE_VAL;
}

// F / F_lim of one contact: the product, 0 without load.
inline double force_ratio(double contact_load, double strength_term)
{
  return contact_load > 0.0 ? contact_load * strength_term : 0.0;
}

}  // namespace crush

#endif

/* The load a Hertzian contact puts on a particle (plain C++): the contact term of the breakage check of
   Ciantia et al. (2014), eq. 2-5, which the contact models publish for each contact.

   With the Hertz contact radius r_H = (3 F r'/(4 E'))^(1/3) (eq. 2), the mean contact pressure is
   p = F / (pi r_H^2), and p^3 = F (4 E'/3)^2 / (pi^3 r'^2): the load F (4 E'/3)^2 / r'^2 recorded
   here is (pi p)^3, and a particle of strength sigma_lim fails when p reaches sigma_lim, i.e. when
   this load reaches (pi sigma_lim)^3 (eq. 5; the strength side is crush_breakage_limit.h).
   r' (eq. 3) = r1 r2/(r1 + r2), a plane: r' = r1; E' (eq. 4) from the two bodies' E and nu. SI units. */
#ifndef HERTZ_MINDLIN_CONTACT_LOAD_H
#define HERTZ_MINDLIN_CONTACT_LOAD_H

namespace crush {

// Elastic constants of one body: Young's modulus E (Pa) and Poisson's ratio nu.
struct Material {
  double youngs_modulus;
  double poisson_ratio;
};

// eq. 4: E' = ((1-nu1^2)/E1 + (1-nu2^2)/E2)^-1 (Pa).
double effective_modulus(const Material &a, const Material &b);

// (4 E'/3)^2 (Pa^2) of a material pair.
inline double limit_factor(double effective_modulus)
{
  const double c = 4.0 * effective_modulus / 3.0;
  return c * c;
}

// The contact's load (Pa^3): F (4 E'/3)^2 / r'^2 = (pi p)^3 for normal force F (N) and r' (m).
inline double contact_load(double normal_force, double effective_radius, double limit_factor)
{
  return normal_force * limit_factor / (effective_radius * effective_radius);
}

}  // namespace crush

#endif

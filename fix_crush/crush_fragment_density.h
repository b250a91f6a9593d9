/* Crushing model (plain C++): the density a fragment is born with (keyword fragment_density).

   'true' (the default): the mother's density; the fragments' mass is their volume's.
   'scaled': density scaling of the fragments, so that no fragment sets a smaller time step than its
   original grain. Both the Rayleigh time, pi r sqrt(rho/G) / (0.1631 nu + 0.8766), and the critical
   step of a Hertzian contact at a given strain, sqrt(m/k) with m ~ rho r^3 and k_N ~ G r (eq. 8),
   scale with r sqrt(rho). A fragment of radius r from a mother of radius R and density rho_R takes
     rho_r = rho_R (R/r)^2,
   which keeps r sqrt(rho): by induction a fragment of any generation has its original grain's
   R_0 sqrt(rho_0), so its original grain's time step. The 14 fragments of one event then weigh 4.33
   times their mother (the 6 large ones x5.83, the 8 small ones x18.9); only inertia grows: contact
   forces, strengths, volumes, porosity and the grading are the same functions of the radii. A
   fragment moves at the inertial number of its grain, (R/r) times its own: the knob is harmless
   while the grains' inertial number is quasi-static. Every fragment keeps its true density
   (rho_R's own true density, inherited), for the outputs that weigh mass. */
#ifndef CRUSH_FRAGMENT_DENSITY_H
#define CRUSH_FRAGMENT_DENSITY_H

namespace crush {

enum class FragmentDensity { true_density, scaled };

// Density (kg/m^3) of a fragment of radius r (m) from a mother of radius R (m) and density rho_R.
inline double fragment_density(FragmentDensity rule, double mother_density, double mother_radius, double radius)
{
  if (rule == FragmentDensity::true_density) return mother_density;
  const double ratio = mother_radius / radius;
  return mother_density * ratio * ratio;
}

}  // namespace crush

#endif

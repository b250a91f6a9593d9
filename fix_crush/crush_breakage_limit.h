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

namespace crush {

// Elastic constants of one body: Young's modulus E (Pa) and Poisson's ratio nu.
struct Material {
  double youngs_modulus;
  double poisson_ratio;
};

// eq. 3: r' = (1/r1 + 1/r2)^-1 (m) of two spheres.
double effective_radius(double r1, double r2);
// eq. 3 for a sphere on a plane (r2 -> infinity): r' = r1.
double effective_radius_plane(double r1);
// eq. 4: E' = ((1-nu1^2)/E1 + (1-nu2^2)/E2)^-1 (Pa).
double effective_modulus(const Material &a, const Material &b);
// eq. 2: Hertz contact radius r_H = (3 F r'/(4 E'))^(1/3) (m) under normal force F (N).
double hertz_contact_radius(double force, double r_eff, double E_eff);
// eq. 5: F_lim (N) for strength sigma_lim (Pa).
double limit_force(double sigma_lim, double r_eff, double E_eff);
// eq. 6/10: sigma_lim = s (d/(N d0))^(-3/m) (Pa) for strength draw s (Pa), diameter d (m),
// reference diameter d0 (m), Weibull modulus m and upscaling factor N.
double size_scaled_strength(double s, double d, double d0, double weibull_m, double scale_factor);

// The breakage check of one contact: F / F_lim, which reaches 1 at breakage. Precomputes what depends
// only on the particle and material pair so that the per-contact cost is one multiply and a cube.
class BreakageLimit {
 public:
  // sigma_lim (Pa): the particle's size-scaled strength; E_eff (Pa): eq. 4 for the contact.
  BreakageLimit(double sigma_lim, double E_eff);
  double limit_force(double r_eff) const;
  double force_ratio(double normal_force, double r_eff) const;

 private:
  double coefficient_;  // [sigma_lim pi (3/(4 E'))^(2/3)]^3, so F_lim = coefficient_ r'^2
};

}  // namespace crush

#endif

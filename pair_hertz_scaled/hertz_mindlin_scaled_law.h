/* Scaled Hertz-Mindlin contact law (plain C++): Ciantia et al. (2014), eq. 8-9, PFC3D's "simplified
   Hertz-Mindlin" with mean-property mixing.

     k_N = 2<G> sqrt(2 D1 D2/(D1+D2)) / (3 (1-<nu>)) sqrt(U)                        (eq. 8)
     k_S = 2 (<G>^2 3 (1-<nu>) D1 D2/(D1+D2))^(1/3) / (2-<nu>) |F_n|^(1/3)         (eq. 9)

   <x> is the mean of the two bodies' values; D1, D2 diameters (m), U the overlap (m), F_n the normal
   force (N) = k_N U, G the shear modulus (Pa). k_N is the secant normal stiffness, k_S the tangent
   shear stiffness used incrementally. Wall convention: a plane is a sphere of infinite diameter made
   of the wall's material, so D1 D2/(D1+D2) -> D1 and the means take the wall's G and nu.
   With D1 D2/(D1+D2) = 2 R*, equal materials reduce eq. 8-9 to LIGGGHTS' hertz / tangential history
   stiffnesses 4/3 Y* sqrt(R* U) and 8 G* sqrt(R* U) (tests/unit/test_contact_law.cpp).
   Also: the Rayleigh critical time step of a sphere. SI units throughout. */
#ifndef HERTZ_MINDLIN_SCALED_LAW_H
#define HERTZ_MINDLIN_SCALED_LAW_H

#include <cmath>

namespace crush {

// Elastic constants for the contact law: shear modulus G (Pa) and Poisson's ratio nu.
struct ShearMaterial {
  double shear_modulus;
  double poisson_ratio;
};

// G = E / (2 (1 + nu)) from LIGGGHTS' youngsModulus and poissonsRatio.
inline ShearMaterial shear_material(double youngs_modulus, double poisson_ratio)
{
  return {youngs_modulus / (2.0 * (1.0 + poisson_ratio)), poisson_ratio};
}

// The material factors of eq. 8-9 for one pair of materials (per LIGGGHTS type pair), so that the
// per-contact cost is one square root. With Dt = D1 D2/(D1+D2):
//   k_N = normal sqrt(Dt U),  normal = 2 sqrt2 <G> / (3 (1-<nu>))                       (eq. 8)
//   k_S = shear sqrt(Dt U),   shear  = 2 (3 <G>^2 (1-<nu>) normal)^(1/3) / (2-<nu>)
// the latter being eq. 9 with |F_n| = k_N U, the elastic normal force, substituted.
struct HertzMindlinCoefficients {
  double normal;
  double shear;
};
HertzMindlinCoefficients hertz_mindlin_coefficients(const ShearMaterial &a, const ShearMaterial &b);

// Dt = D1 D2/(D1+D2) (m) of a ball-ball contact from the radii; for a plane (infinite radius) Dt = D1.
inline double diameter_term_from_radii(double r1, double r2) { return 2.0 * r1 * r2 / (r1 + r2); }

// eq. 8-9 at one contact: the secant normal stiffness k_N and the tangent shear stiffness k_S (N/m)
// at overlap U (m) for diameter term Dt (m). The one place the law is evaluated: the contact models,
// the servo walls and the automatic time step all call it. One square root serves both.
struct HertzMindlinStiffness {
  double normal;
  double shear;
};

inline HertzMindlinStiffness contact_stiffness(const HertzMindlinCoefficients &c, double diameter_term,
                                               double overlap)
{
  const double root = std::sqrt(diameter_term * overlap);
  return {c.normal * root, c.shear * root};
}

// dF_n/dU = 1.5 k_N: the tangent of F_n = k_N U with k_N ~ sqrt(U), for stability and servo gains.
inline double tangent_normal_stiffness(double secant_normal_stiffness) { return 1.5 * secant_normal_stiffness; }

// Rayleigh critical time step (s) of a sphere of radius r (m), density rho (kg/m^3):
//   t_R = pi r sqrt(rho/G) / (0.1631 nu + 0.8766)
double rayleigh_time_step(double radius, double density, const ShearMaterial &m);

}  // namespace crush

#endif

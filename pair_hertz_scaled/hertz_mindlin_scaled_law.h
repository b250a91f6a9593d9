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

inline double normal_stiffness(const HertzMindlinCoefficients &c, double diameter_term, double overlap)
{
  return c.normal * std::sqrt(diameter_term * overlap);
}

inline double shear_stiffness(const HertzMindlinCoefficients &c, double diameter_term, double overlap)
{
  return c.shear * std::sqrt(diameter_term * overlap);
}

// eq. 8-9 for one contact geometry, in the paper's form (|F_n| enters eq. 9 as given).
class HertzMindlinScaled {
 public:
  // Ball-ball contact of diameters d1, d2 (m).
  HertzMindlinScaled(const ShearMaterial &a, const ShearMaterial &b, double d1, double d2);
  // Ball-plane contact: the plane is a sphere of infinite diameter made of material b.
  static HertzMindlinScaled ball_plane(const ShearMaterial &ball, const ShearMaterial &wall, double d);

  // eq. 8: secant normal stiffness (N/m) at overlap U (m).
  double normal_stiffness(double overlap) const;
  // F_n = k_N U (N).
  double normal_force(double overlap) const;
  // eq. 9: tangent shear stiffness (N/m) under normal force |F_n| (N).
  double shear_stiffness(double normal_force) const;

  // D1 D2/(D1+D2) (m); 2 R* in terms of radii.
  double diameter_term() const { return diameter_term_; }

 private:
  HertzMindlinScaled(const ShearMaterial &a, const ShearMaterial &b, double diameter_term, bool);
  double diameter_term_;
  double normal_coefficient_;  // k_N / sqrt(U)
  double shear_coefficient_;   // k_S / |F_n|^(1/3) (eq. 9)
};

// Young's modulus from G and nu: E = 2 G (1 + nu).
double youngs_modulus(const ShearMaterial &m);

// Rayleigh critical time step (s) of a sphere of radius r (m), density rho (kg/m^3):
//   t_R = pi r sqrt(rho/G) / (0.1631 nu + 0.8766)
double rayleigh_time_step(double radius, double density, const ShearMaterial &m);

}  // namespace crush

#endif

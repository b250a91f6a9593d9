/* Scaled Hertz-Mindlin contact law (plain C++): eq. 8-9 (see hertz_mindlin_scaled_law.h). */
#include "hertz_mindlin_scaled_law.h"

#include <cmath>

#include "crush_constants.h"
#include "crush_model_error.h"

namespace crush {

static void check_material(const ShearMaterial &m)
{
  require(m.shear_modulus > 0.0, "shear modulus G", m.shear_modulus, "> 0 Pa");
  require(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5, "poisson_ratio", m.poisson_ratio,
          "in (-1, 0.5)");
}

static double diameter_product_ratio(double d1, double d2)
{
  require(d1 > 0.0, "diameter d1", d1, "> 0 m");
  require(d2 > 0.0, "diameter d2", d2, "> 0 m");
  return d1 * d2 / (d1 + d2);
}

HertzMindlinScaled::HertzMindlinScaled(const ShearMaterial &a, const ShearMaterial &b, double d1,
                                       double d2) :
    HertzMindlinScaled(a, b, diameter_product_ratio(d1, d2), true)
{
}

HertzMindlinScaled HertzMindlinScaled::ball_plane(const ShearMaterial &ball, const ShearMaterial &wall,
                                                  double d)
{
  require(d > 0.0, "diameter d1", d, "> 0 m");
  return HertzMindlinScaled(ball, wall, d, true);
}

HertzMindlinScaled::HertzMindlinScaled(const ShearMaterial &a, const ShearMaterial &b,
                                       double diameter_term, bool) :
    diameter_term_(diameter_term)
{
  check_material(a);
  check_material(b);
  const double G = 0.5 * (a.shear_modulus + b.shear_modulus);
  const double nu = 0.5 * (a.poisson_ratio + b.poisson_ratio);
  normal_coefficient_ = 2.0 * G * std::sqrt(2.0 * diameter_term) / (3.0 * (1.0 - nu));
  shear_coefficient_ = 2.0 * std::cbrt(G * G * 3.0 * (1.0 - nu) * diameter_term) / (2.0 - nu);
}

HertzMindlinCoefficients hertz_mindlin_coefficients(const ShearMaterial &a, const ShearMaterial &b)
{
  check_material(a);
  check_material(b);
  const double G = 0.5 * (a.shear_modulus + b.shear_modulus);
  const double nu = 0.5 * (a.poisson_ratio + b.poisson_ratio);
  HertzMindlinCoefficients c;
  c.normal = 2.0 * std::sqrt(2.0) * G / (3.0 * (1.0 - nu));
  c.shear = 2.0 * std::cbrt(3.0 * G * G * (1.0 - nu) * c.normal) / (2.0 - nu);
  return c;
}

double HertzMindlinScaled::normal_stiffness(double overlap) const
{
  return overlap > 0.0 ? normal_coefficient_ * std::sqrt(overlap) : 0.0;
}

double HertzMindlinScaled::normal_force(double overlap) const
{
  return normal_stiffness(overlap) * overlap;
}

double HertzMindlinScaled::shear_stiffness(double normal_force) const
{
  return shear_coefficient_ * std::cbrt(std::fabs(normal_force));
}

double youngs_modulus(const ShearMaterial &m)
{
  check_material(m);
  return 2.0 * m.shear_modulus * (1.0 + m.poisson_ratio);
}

double rayleigh_time_step(double radius, double density, const ShearMaterial &m)
{
  require(radius > 0.0, "radius", radius, "> 0 m");
  require(density > 0.0, "density", density, "> 0 kg/m^3");
  check_material(m);
  return pi * radius * std::sqrt(density / m.shear_modulus) / (0.1631 * m.poisson_ratio + 0.8766);
}

}  // namespace crush

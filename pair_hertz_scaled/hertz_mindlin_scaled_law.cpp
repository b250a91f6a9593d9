/* Scaled Hertz-Mindlin contact law (plain C++): eq. 8-9 (see hertz_mindlin_scaled_law.h). */
#include "hertz_mindlin_scaled_law.h"

#include <cmath>

#include "crush_constants.h"
#include "crush_model_error.h"

namespace crush {

static void check_material(const ShearMaterial &m)
{
  // above 1e13 Pa no solid (diamond: G = 5e11 Pa): the forces would overflow before anything moved
  require(m.shear_modulus > 0.0 && m.shear_modulus <= 1e13, "shear modulus G", m.shear_modulus, "in (0, 1e13] Pa");
  require(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5, "poisson_ratio", m.poisson_ratio,
          "in (-1, 0.5)");
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

double rayleigh_time_step(double radius, double density, const ShearMaterial &m)
{
  require(radius > 0.0, "radius", radius, "> 0 m");
  require(density > 0.0, "density", density, "> 0 kg/m^3");
  check_material(m);
  return pi * radius * std::sqrt(density / m.shear_modulus) / (0.1631 * m.poisson_ratio + 0.8766);
}

}  // namespace crush

/* Crushing model (plain C++): breakage limit, eq. 2-7 and 10 of Ciantia et al. (2014). */
#include "crush_breakage_limit.h"

#include <cmath>

#include "crush_constants.h"
#include "crush_model_error.h"

namespace crush {

double effective_radius(double r1, double r2)
{
  require(r1 > 0.0, "radius r1", r1, "> 0 m");
  require(r2 > 0.0, "radius r2", r2, "> 0 m");
  return r1 * r2 / (r1 + r2);
}

double effective_radius_plane(double r1)
{
  require(r1 > 0.0, "radius r1", r1, "> 0 m");
  return r1;
}

static void check_material(const Material &m)
{
  require(m.youngs_modulus > 0.0, "youngs_modulus", m.youngs_modulus, "> 0 Pa");
  require(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5, "poisson_ratio", m.poisson_ratio,
          "in (-1, 0.5)");
}

double effective_modulus(const Material &a, const Material &b)
{
  check_material(a);
  check_material(b);
  const double compliance = (1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                            (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus;
  return 1.0 / compliance;
}

double hertz_contact_radius(double force, double r_eff, double E_eff)
{
  require(force >= 0.0, "normal force", force, ">= 0 N");
  require(r_eff > 0.0, "effective radius", r_eff, "> 0 m");
  require(E_eff > 0.0, "effective modulus", E_eff, "> 0 Pa");
  return std::cbrt(3.0 * force * r_eff / (4.0 * E_eff));
}

double limit_force(double sigma_lim, double r_eff, double E_eff)
{
  require(r_eff > 0.0, "effective radius", r_eff, "> 0 m");
  return BreakageLimit(sigma_lim, E_eff).limit_force(r_eff);
}

double size_scaled_strength(double s, double d, double d0, double weibull_m, double scale_factor)
{
  require(s >= 0.0, "strength draw", s, ">= 0 Pa");
  require(d > 0.0, "diameter d", d, "> 0 m");
  require(d0 > 0.0, "d0", d0, "> 0 m");
  require(weibull_m > 0.0, "weibull_m", weibull_m, "> 0");
  require(scale_factor > 0.0, "scale_factor", scale_factor, "> 0");
  return s * std::pow(d / (scale_factor * d0), -3.0 / weibull_m);
}

BreakageLimit::BreakageLimit(double sigma_lim, double E_eff)
{
  require(sigma_lim >= 0.0, "sigma_lim", sigma_lim, ">= 0 Pa");
  require(E_eff > 0.0, "effective modulus", E_eff, "> 0 Pa");
  // (3 r'/(4E'))^(2/3) cubed is (3 r'/(4E'))^2: F_lim = (sigma_lim pi)^3 (3/(4E'))^2 r'^2.
  const double a = sigma_lim * pi;
  const double b = 3.0 / (4.0 * E_eff);
  coefficient_ = a * a * a * b * b;
}

double BreakageLimit::limit_force(double r_eff) const
{
  return coefficient_ * r_eff * r_eff;
}

double BreakageLimit::force_ratio(double normal_force, double r_eff) const
{
  const double f_lim = limit_force(r_eff);
  // A zero-strength particle breaks under any compressive contact.
  if (f_lim <= 0.0) return normal_force > 0.0 ? HUGE_VAL : 0.0;
  return normal_force / f_lim;
}

}  // namespace crush

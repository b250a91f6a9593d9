/* Crushing model (plain C++): the bound of fix crush's exact adaptive check (crush_check_bound.h). */
#include "crush_check_bound.h"

#include <cmath>
#include <limits>

namespace crush {

namespace {
const double margin = 1e-6;
}

double ratio_coefficient(double normal_coefficient, double limit_factor)
{
  return std::sqrt(2.0) * normal_coefficient * limit_factor;
}

double ratio_growth(double ratio_coefficient, double strength_term, double radius, double smallest_radius)
{
  if (std::isinf(strength_term)) return std::numeric_limits<double>::infinity();
  const double smallest_effective_radius = radius * smallest_radius / (radius + smallest_radius);
  return std::cbrt(ratio_coefficient * strength_term * ratio_coefficient * strength_term) / smallest_effective_radius;
}

double allowed_displacement(double ratio, double growth)
{
  const double slack = 1.0 - margin - std::cbrt(ratio * ratio);
  if (!(slack > 0.0) || std::isinf(growth)) return 0.0;
  return growth > 0.0 ? slack / (2.0 * growth) : std::numeric_limits<double>::infinity();
}

}  // namespace crush

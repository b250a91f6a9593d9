/* Crushing model (plain C++): breakage limit, eq. 2-7 and 10 of Ciantia et al. (2014). */
#include "crush_breakage_limit.h"

#include <cmath>

#include "crush_model_error.h"

namespace crush {

double size_scaled_strength(double s, double d, double d0, double weibull_m, double scale_factor)
{
  require(s >= 0.0, "strength draw", s, ">= 0 Pa");
  require(d > 0.0, "diameter d", d, "> 0 m");
  require(d0 > 0.0, "d0", d0, "> 0 m");
  require(weibull_m > 0.0, "weibull_m", weibull_m, "> 0");
  require(scale_factor > 0.0, "scale_factor", scale_factor, "> 0");
  return s * std::pow(d / (scale_factor * d0), -3.0 / weibull_m);
}

}  // namespace crush

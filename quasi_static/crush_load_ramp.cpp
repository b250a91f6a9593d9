/* Crushing model (plain C++): load ramp, eq. 11 (see crush_load_ramp.h). */
#include "crush_load_ramp.h"

#include <cmath>

#include "crush_model_error.h"

namespace crush {

LoadRamp::LoadRamp(double load_rate, double sigma_ref) : load_rate_(load_rate), sigma_ref_(sigma_ref)
{
  require(load_rate > 0.0, "load_rate L_R", load_rate, "> 0");
  require(sigma_ref > 0.0, "sigma_ref", sigma_ref, "> 0 Pa");
}

double LoadRamp::increment(double sigma) const
{
  require(sigma > 0.0, "stress sigma", sigma, "> 0 Pa (eq. 11 takes its logarithm)");
  return load_rate_ * sigma_ref_ * (1.0 + std::log(sigma / sigma_ref_));
}

long LoadRamp::steps_to_reach(double sigma_start, double sigma_end) const
{
  require(sigma_start >= sigma_ref_ / std::exp(1.0), "start stress", sigma_start,
          ">= sigma_ref/e (below it eq. 11 decreases the stress)");
  long steps = 0;
  for (double sigma = sigma_start; sigma < sigma_end; sigma = next(sigma)) ++steps;
  return steps;
}

}  // namespace crush

/* Crushing model (plain C++): strength draws (see crush_strength.h). */
#include "crush_strength.h"

#include <algorithm>
#include <cmath>

#include "crush_constants.h"
#include "crush_model_error.h"
#include "crush_random.h"

namespace crush {

StrengthDraw::StrengthDraw(StrengthDistribution distribution, double sigma_lim0, double cv,
                           double weibull_m, std::uint64_t seed) :
    distribution_(distribution), sigma_lim0_(sigma_lim0), cv_(cv), weibull_m_(weibull_m), seed_(seed)
{
  require(sigma_lim0 > 0.0, "sigma_lim0", sigma_lim0, "> 0 Pa");
  require(cv >= 0.0, "cv", cv, ">= 0");
  require(weibull_m > 0.0, "weibull_m", weibull_m, "> 0");
}

double StrengthDraw::draw(std::uint64_t tag, int generation) const
{
  switch (distribution_) {
    case StrengthDistribution::normal: return draw_normal(tag);
    case StrengthDistribution::normal_clipped: return draw_normal_clipped(tag);
    case StrengthDistribution::normal_clipped_originals:
      return generation == 0 ? draw_normal_clipped(tag) : draw_normal(tag);
    case StrengthDistribution::weibull: return draw_weibull(tag);
    case StrengthDistribution::constant: break;
  }
  return sigma_lim0_;
}

double StrengthDraw::draw_normal(std::uint64_t tag) const
{
  // Box-Muller on successive counters; redraw until positive. P(s <= 0) = Phi(-1/cv) <= 0.16 for
  // cv <= 1, so the loop ends almost at once; its bound only guards absurd cv values.
  const double sd = cv_ * sigma_lim0_;
  for (std::uint64_t k = 0; k < 4096; k += 2) {
    const double u1 = uniform_open(seed_, tag, Stream::strength, k);
    const double u2 = uniform_open(seed_, tag, Stream::strength, k + 1);
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * pi * u2;
    for (double z : {radius * std::cos(angle), radius * std::sin(angle)}) {
      const double s = sigma_lim0_ + sd * z;
      if (s > 0.0) return s;
    }
  }
  return sigma_lim0_;  // unreachable for cv < 100 (probability < 1e-1000)
}

double StrengthDraw::draw_normal_clipped(std::uint64_t tag) const
{
  const double u1 = uniform_open(seed_, tag, Stream::strength, 0);
  const double u2 = uniform_open(seed_, tag, Stream::strength, 1);
  const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * pi * u2);
  return std::max(0.0, sigma_lim0_ + cv_ * sigma_lim0_ * z);
}

double StrengthDraw::draw_weibull(std::uint64_t tag) const
{
  const double scale = sigma_lim0_ / std::tgamma(1.0 + 1.0 / weibull_m_);
  const double u = uniform_open(seed_, tag, Stream::strength, 0);
  return scale * std::pow(-std::log(u), 1.0 / weibull_m_);
}

double StrengthDraw::mean() const
{
  if (distribution_ == StrengthDistribution::normal)
    return truncated_normal_mean(sigma_lim0_, cv_ * sigma_lim0_);
  if (distribution_ == StrengthDistribution::normal_clipped ||
      distribution_ == StrengthDistribution::normal_clipped_originals)
    return clipped_normal_mean(sigma_lim0_, cv_ * sigma_lim0_);
  return sigma_lim0_;
}

double StrengthDraw::cv() const
{
  switch (distribution_) {
    case StrengthDistribution::normal: return truncated_normal_cv(sigma_lim0_, cv_ * sigma_lim0_);
    case StrengthDistribution::normal_clipped:
    case StrengthDistribution::normal_clipped_originals: return clipped_normal_cv(sigma_lim0_, cv_ * sigma_lim0_);
    case StrengthDistribution::weibull: {
      const double g1 = std::tgamma(1.0 + 1.0 / weibull_m_);
      const double g2 = std::tgamma(1.0 + 2.0 / weibull_m_);
      return std::sqrt(g2 / (g1 * g1) - 1.0);
    }
    case StrengthDistribution::constant: break;
  }
  return 0.0;
}

// Truncation at 0 of N(mu, sigma^2): with a = -mu/sigma and lambda = phi(a)/(1 - Phi(a)),
// mean = mu + sigma lambda and variance = sigma^2 [1 + a lambda - lambda^2].
static double inverse_mills(double a)
{
  const double phi = std::exp(-0.5 * a * a) / std::sqrt(2.0 * pi);
  const double upper_tail = 0.5 * std::erfc(a / std::sqrt(2.0));
  return phi / upper_tail;
}

double truncated_normal_mean(double mu, double sigma)
{
  require(mu > 0.0, "mean", mu, "> 0");
  require(sigma >= 0.0, "standard deviation", sigma, ">= 0");
  if (sigma == 0.0) return mu;
  return mu + sigma * inverse_mills(-mu / sigma);
}

double truncated_normal_cv(double mu, double sigma)
{
  require(mu > 0.0, "mean", mu, "> 0");
  require(sigma >= 0.0, "standard deviation", sigma, ">= 0");
  if (sigma == 0.0) return 0.0;
  const double a = -mu / sigma;
  const double lambda = inverse_mills(a);
  const double variance = sigma * sigma * (1.0 + a * lambda - lambda * lambda);
  return std::sqrt(variance) / truncated_normal_mean(mu, sigma);
}

// max(0, X), X ~ N(mu, sigma^2), a = mu/sigma: E = mu Phi(a) + sigma phi(a),
// E[Y^2] = (mu^2 + sigma^2) Phi(a) + mu sigma phi(a).
static void clipped_normal_moments(double mu, double sigma, double &first, double &second)
{
  require(mu > 0.0, "mean", mu, "> 0");
  require(sigma >= 0.0, "standard deviation", sigma, ">= 0");
  if (sigma == 0.0) {
    first = mu;
    second = mu * mu;
    return;
  }
  const double a = mu / sigma;
  const double phi = std::exp(-0.5 * a * a) / std::sqrt(2.0 * pi);
  const double Phi = 0.5 * std::erfc(-a / std::sqrt(2.0));
  first = mu * Phi + sigma * phi;
  second = (mu * mu + sigma * sigma) * Phi + mu * sigma * phi;
}

double clipped_normal_mean(double mu, double sigma)
{
  double first, second;
  clipped_normal_moments(mu, sigma, first, second);
  return first;
}

double clipped_normal_cv(double mu, double sigma)
{
  double first, second;
  clipped_normal_moments(mu, sigma, first, second);
  return std::sqrt(std::max(0.0, second - first * first)) / first;
}

}  // namespace crush

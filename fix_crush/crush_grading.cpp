/* Crushing model (plain C++): grading and grading index (see crush_grading.h). */
#include "crush_grading.h"

#include <cmath>
#include <utility>

#include "crush_constants.h"
#include "crush_model_error.h"

namespace crush {

double fractal_passing(double d, double d_max, double fractal_dimension)
{
  require(d_max > 0.0, "fines largest size", d_max, "> 0 m");
  require(fractal_dimension < 3.0, "fines_dimension", fractal_dimension, "< 3");
  if (d <= 0.0) return 0.0;
  if (d >= d_max) return 1.0;
  return std::pow(d / d_max, 3.0 - fractal_dimension);
}

Grading::Grading(std::vector<double> sieves, double scale_factor, double fractal_dimension) :
    sieves_(std::move(sieves)), scale_factor_(scale_factor), fractal_dimension_(fractal_dimension)
{
  require(scale_factor > 0.0, "scale_factor", scale_factor, "> 0");
  require(fractal_dimension < 3.0, "fines_dimension", fractal_dimension, "< 3");
  for (std::size_t k = 0; k < sieves_.size(); ++k) {
    require(sieves_[k] > 0.0, "sieve size", sieves_[k], "> 0 m");
    if (k > 0) require(sieves_[k] > sieves_[k - 1], "sieve size", sieves_[k], "ascending sizes");
  }
}

GradingSums Grading::empty_sums() const
{
  GradingSums sums;
  sums.volume_passing.assign(sieves_.size(), 0.0);
  return sums;
}

void Grading::add_grain(double diameter, GradingSums &sums) const
{
  add_volume(diameter, sphere_volume(diameter), sums);
}

void Grading::add_volume(double diameter, double volume, GradingSums &sums) const
{
  const double size = diameter / scale_factor_;
  sums.volume += volume;
  sums.volume_times_size += volume * size;
  // Sieves are ascending: the grain passes every sieve from the first one larger than it.
  for (std::size_t k = sieves_.size(); k-- > 0 && sieves_[k] > size;) sums.volume_passing[k] += volume;
}

double Grading::fines_passing(double size, double fines_size) const
{
  return fractal_passing(size, fines_size, fractal_dimension_);
}

std::vector<double> Grading::percent_passing(const GradingSums &sums, double removed_volume,
                                             double fines_max_diameter) const
{
  require(removed_volume >= 0.0, "removed volume", removed_volume, ">= 0 m^3");
  const double total = sums.volume + removed_volume;
  require(total > 0.0, "solid volume", total, "> 0 m^3");
  std::vector<double> out(sieves_.size());
  const double fines_size = fines_max_diameter / scale_factor_;
  for (std::size_t k = 0; k < sieves_.size(); ++k) {
    const double fines = removed_volume > 0.0 ? removed_volume * fines_passing(sieves_[k], fines_size)
                                              : 0.0;
    out[k] = 100.0 * (sums.volume_passing[k] + fines) / total;
  }
  return out;
}

double Grading::grading_index(const GradingSums &sums, double removed_volume, double fines_max_diameter,
                              double d_max) const
{
  require(d_max > 0.0, "d_max", d_max, "> 0 m");
  require(removed_volume >= 0.0, "removed volume", removed_volume, ">= 0 m^3");
  const double total = sums.volume + removed_volume;
  require(total > 0.0, "solid volume", total, "> 0 m^3");
  const double shape = 4.0 - fractal_dimension_;  // integral of (d/d_f)^(3-D) over [0, d_f] is d_f/shape
  double area = d_max * sums.volume - sums.volume_times_size;
  if (removed_volume > 0.0) {
    const double fines_size = fines_max_diameter / scale_factor_;
    area += removed_volume * (fines_size / shape + d_max - fines_size);
  }
  return (area / total) / (d_max / shape);
}

}  // namespace crush

/* Crushing model (plain C++): grain size distribution (GSD) with the removed volume as fractal fines,
   and the grading index I_G (Ciantia et al. 2014, sec. 2.2 and 4.1, Fig. 6).

   - Percent passing by mass at a sieve s (all grains have one density, so mass ~ volume): the volume
     of grains with d/N < s, plus the removed volume V_r distributed as a fractal fine fraction whose
     passing fraction is (s/d_f)^(3-D) below its largest size d_f (capped at 1), over the total solid
     volume. N is the upscaling factor: model diameters are divided by N (downscaling, sec. 2.4).
   - Grading index (Muir Wood's grading state index, D. Muir Wood 2007, "The magic of sands",
     Proc. ICE Geotech. Eng. 160(GE2); Muir Wood & Maeda 2008, Acta Geotech. 3:3-14):
       I_G = (area under the current cumulative grading F(d)) / (area under the limiting grading
             F_L(d) = (d/d_max)^(3-D)), both on a linear size axis over [0, d_max].
     On [0, d_max] the area under F_L is d_max/(4-D); a grain of size d adds (d_max - d) times its
     mass fraction, and the fractal fines add V_r/V (d_f/(4-D) + d_max - d_f). So I_G = 0 for a
     single size at d_max, 1 for the limiting grading. A Fontainebleau-like grading (d50 = 0.21 mm)
     gives I_G close to the paper's initial 0.735 (tests/unit/test_grading.cpp); areas on a log axis
     would give about 0.2, so the linear axis is the definition the paper used.
   The sums over grains are kept separate (GradingSums) so that an MPI adapter can add them across
   processors before finishing the curve. SI units: m, m^3. */
#ifndef CRUSH_GRADING_H
#define CRUSH_GRADING_H

#include <vector>

namespace crush {

// Volume sums over grains, additive across processors.
struct GradingSums {
  std::vector<double> volume_passing;  // per sieve: volume of grains with d/N < sieve (m^3)
  double volume = 0.0;                 // volume of all grains (m^3)
  double volume_times_size = 0.0;      // sum of V d/N over grains (m^4), for I_G
};

class Grading {
 public:
  // sieves: downscaled sieve sizes (m), ascending, > 0; scale_factor N > 0; fractal_dimension D < 3.
  Grading(std::vector<double> sieves, double scale_factor, double fractal_dimension = 2.5);

  GradingSums empty_sums() const;
  // Adds one grain of model diameter d (m).
  void add_grain(double diameter, GradingSums &sums) const;
  // Adds a size class: solid volume (m^3) of grains of model diameter d (m).
  void add_volume(double diameter, double volume, GradingSums &sums) const;

  // Percent passing by mass at each sieve; removed_volume (m^3, model scale) is placed as fines
  // whose largest model diameter is fines_max_diameter (m).
  std::vector<double> percent_passing(const GradingSums &sums, double removed_volume,
                                      double fines_max_diameter) const;
  // I_G against the limiting grading of largest (downscaled) size d_max (m); grains must be <= d_max.
  double grading_index(const GradingSums &sums, double removed_volume, double fines_max_diameter,
                       double d_max) const;

  const std::vector<double> &sieves() const { return sieves_; }
  double scale_factor() const { return scale_factor_; }

 private:
  double fines_passing(double size, double fines_size) const;

  std::vector<double> sieves_;
  double scale_factor_, fractal_dimension_;
};

// Passing fraction of a fractal grading of largest size d_max: (d/d_max)^(3-D), capped to [0, 1].
double fractal_passing(double d, double d_max, double fractal_dimension);

}  // namespace crush

#endif

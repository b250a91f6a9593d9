/* Crushing model (plain C++): the load ramp of Ciantia et al. (2014), eq. 11.

     sigma(i+1) = sigma(i) + L_R [sigma_ref + ln(sigma(i)/sigma_ref)]

   with the natural logarithm and sigma_ref = 1 kPa. Eq. 11 adds a stress and a pure number; it is
   read in kPa (sigma_ref = 1), which in any unit is sigma_ref [1 + ln(sigma/sigma_ref)]: the form
   used here, exact for sigma_ref = 1 kPa. From 1 kPa to 100 MPa at L_R = 0.1 it takes 87,7xx steps
   (tests/unit/test_load_ramp.cpp asserts the exact count and a closed-form bound). SI units: Pa. */
#ifndef CRUSH_LOAD_RAMP_H
#define CRUSH_LOAD_RAMP_H

namespace crush {

class LoadRamp {
 public:
  // load_rate L_R > 0; sigma_ref (Pa) > 0 (the paper: 1e3 Pa).
  explicit LoadRamp(double load_rate, double sigma_ref = 1.0e3);

  // The increment added to sigma (Pa) in one step; sigma >= sigma_ref / e keeps it non-negative.
  double increment(double sigma) const;
  // One step of eq. 11.
  double next(double sigma) const { return sigma + increment(sigma); }
  // Number of steps of eq. 11 from sigma_start until the stress reaches sigma_end (Pa).
  long steps_to_reach(double sigma_start, double sigma_end) const;

  double load_rate() const { return load_rate_; }
  double sigma_ref() const { return sigma_ref_; }

 private:
  double load_rate_, sigma_ref_;
};

}  // namespace crush

#endif

/* Crushing model (plain C++): the per-particle strength draw s of Ciantia et al. (2014), sec. 2.1.

   The paper draws the limit strength from a normal distribution with mean sigma_lim0 and coefficient
   of variation CV; its Table 1 has CV = 1, for which a plain normal draw is negative one time in six.
   Distributions offered (the choice is the user's and is documented in doc/fix_crush.txt):
   - normal (default): the normal N(sigma_lim0, (CV sigma_lim0)^2) truncated to s > 0, sampled by
     redrawing until positive. Its mean and CV are those of the truncated distribution, given in closed
     form by truncated_normal_mean() / truncated_normal_cv(); for CV = 1 the mean is 1.288 sigma_lim0.
   - normal_clipped: the plain normal N(sigma_lim0, (CV sigma_lim0)^2), a negative draw clipped to
     s = 0 (that particle breaks under its first load). A PFC implementation that draws the normal
     without guarding its sign behaves like this; for CV = 1 one particle in six, fragments included,
     breaks at its first contact. Mean and CV: clipped_normal_mean() / clipped_normal_cv().
   - normal_clipped_originals: original grains (generation 0) draw like normal_clipped, fragments
     like normal. One original grain in six (CV = 1) has zero strength and breaks at its first load;
     fragments never do, so there is no cascade. The reading of the paper's Table 3, where the
     events per initial grain (17-23%) are Phi(-1) = 15.9% plus the few percent that the
     truncated draw breaks by 100 MPa (studies/fontainebleau/README.md).
   - weibull: P(s) = 1 - exp(-(s/s0)^m) with m = weibull_m and s0 chosen so that the mean is sigma_lim0
     (the CV then follows from m: 0.120 for m = 10).
   - constant: s = sigma_lim0 for every particle.
   Draws are pure functions of (seed, tag), see crush_random.h. The size effect (eq. 6/10) is applied
   on top of s by size_scaled_strength() (crush_breakage_limit.h). SI units: Pa. */
#ifndef CRUSH_STRENGTH_H
#define CRUSH_STRENGTH_H

#include <cstdint>

namespace crush {

enum class StrengthDistribution { normal, normal_clipped, normal_clipped_originals, weibull, constant };

class StrengthDraw {
 public:
  // sigma_lim0 (Pa) > 0; cv >= 0 (normal only); weibull_m > 0 (weibull only).
  StrengthDraw(StrengthDistribution distribution, double sigma_lim0, double cv, double weibull_m,
               std::uint64_t seed);

  // The strength s (Pa) of the particle with this tag and generation (0: an original grain); > 0
  // (normal_clipped, and normal_clipped_originals at generation 0: >= 0).
  double draw(std::uint64_t tag, int generation = 0) const;
  // Mean and coefficient of variation of the distribution actually sampled (for
  // normal_clipped_originals: that of the original grains).
  double mean() const;
  double cv() const;

 private:
  double draw_normal(std::uint64_t tag) const;
  double draw_normal_clipped(std::uint64_t tag) const;
  double draw_weibull(std::uint64_t tag) const;

  StrengthDistribution distribution_;
  double sigma_lim0_, cv_, weibull_m_;
  std::uint64_t seed_;
};

// Mean and CV of N(mu, sigma^2) truncated to (0, inf), mu > 0, sigma >= 0.
double truncated_normal_mean(double mu, double sigma);
double truncated_normal_cv(double mu, double sigma);
// Mean and CV of max(0, X) for X ~ N(mu, sigma^2), mu > 0.
double clipped_normal_mean(double mu, double sigma);
double clipped_normal_cv(double mu, double sigma);

}  // namespace crush

#endif

/* Crushing model (plain C++): fix crush settings (see crush_settings.h). */
#include "crush_settings.h"

#include "crush_breakage_limit.h"
#include "crush_model_error.h"
#include "crush_keywords.h"

namespace crush {

double CrushSettings::size_scaled(double s, double d) const
{
  return size_effect ? size_scaled_strength(s, d, d0, weibull_m, scale_factor) : s;
}

CrushSettings parse_crush_settings(const std::vector<std::string> &args)
{
  CrushSettings c;
  long seed = 0, every = 1;
  int orientation = 0, distribution = static_cast<int>(c.distribution), layout = static_cast<int>(c.layout);
  KeywordTable t;
  t.number("sigma_lim0", "a strength > 0 (Pa)", positive(), c.sigma_lim0, true)
   .number("cv", "a coefficient of variation >= 0", at_least(0.0), c.cv, true)
   .number("weibull_m", "a Weibull modulus > 0", positive(), c.weibull_m, true)
   .number("d0", "a reference diameter > 0 (m)", positive(), c.d0, true)
   .integer("seed", "a positive integer", 1, seed, true)
   .number("scale", "an upscaling factor N > 0", positive(), c.scale_factor)
   .number("dmin", "a diameter >= 0 (m)", at_least(0.0), c.dmin)
   .add("every", "an integer >= 1 or 'adaptive'", [&](const std::vector<std::string> &w, std::size_t at) {
     if (at + 1 < w.size() && w[at + 1] == "adaptive") {
       c.adaptive = true;
       return std::size_t(1);
     }
     c.adaptive = false;
     every = t.whole("every", w, at + 1, 1, 1000000000L);
     return std::size_t(1);
   })
   .choice("orientation", {"random", "fixed"}, orientation)
   // the order of StrengthDistribution and FragmentLayout
   .choice("distribution", {"normal", "normal_clipped", "normal_clipped_originals", "weibull", "constant"},
           distribution)
   .yes_no("size_effect", c.size_effect)
   .choice("layout", {"fourteen", "tetrahedral"}, layout)
   .number("fines_dimension", "a fractal dimension < 3", below(3.0), c.fines_dimension)
   .number("rayleigh_fraction", "a fraction in (0, 1]", open_closed(0.0, 1.0), c.rayleigh_fraction)
   .text("log", "a file name", c.log_file)
   .text("region", "a region ID", c.region_id)
   .yes_no("check_tags", c.check_tags);
  t.parse(args);
  c.seed = static_cast<std::uint64_t>(seed);
  c.every = static_cast<int>(every);
  c.random_orientation = orientation == 0;
  c.distribution = static_cast<StrengthDistribution>(distribution);
  c.layout = static_cast<FragmentLayout>(layout);
  return c;
}

}  // namespace crush

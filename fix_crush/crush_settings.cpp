/* Crushing model (plain C++): fix crush settings (see crush_settings.h). */
#include "crush_settings.h"

#include "crush_breakage_limit.h"
#include "crush_model_error.h"
#include "crush_keywords.h"

#include <sstream>

namespace crush {

double CrushSettings::size_scaled(double s, double d) const
{
  return size_scaled(s, d, scale_factor);
}

double CrushSettings::size_scaled(double s, double d, double particle_scale) const
{
  return size_effect ? size_scaled_strength(s, d, d0, weibull_m, particle_scale) : s;
}

CrushSettings parse_crush_settings(const std::vector<std::string> &args)
{
  CrushSettings c;
  long seed = 0, every = 1;
  int orientation = 0, force = 0, fragment_density = 0, event_lists = 0, distribution = static_cast<int>(c.distribution), layout = static_cast<int>(c.layout);
  KeywordTable t;
  // Ranges: what has a physical meaning (doc/fix_crush.txt); suspicious_settings() warns inside them.
  t.number("sigma_lim0", "a strength in [1e3, 1e30] Pa", in_range(1e3, 1e30, true), c.sigma_lim0, true)
   .number("cv", "a coefficient of variation in [0, 10]", in_range(0.0, 10.0, true), c.cv, true)
   .number("weibull_m", "a Weibull modulus in [0.5, 1000]", in_range(0.5, 1000.0, true), c.weibull_m, true)
   .number("d0", "a reference diameter in [1e-7, 10] m", in_range(1e-7, 10.0, true), c.d0, true)
   .integer("seed", "a positive integer", 1, seed, true)
   .number("scale", "an upscaling factor N in (0, 1e4]", open_closed(0.0, 1e4), c.scale_factor)
   .text("scale_atom", "the name of a scalar fix property/atom holding each particle's N", c.scale_atom)
   .number("dmin", "a diameter in [0, 10] m", in_range(0.0, 10.0, true), c.dmin)
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
   .number("fines_dimension", "a fractal dimension in [0, 3)", in_range(0.0, 3.0, false), c.fines_dimension)
   .number("rayleigh_fraction", "a fraction in (0, 1]", open_closed(0.0, 1.0), c.rayleigh_fraction)
   .text("log", "a file name", c.log_file)
   .text("region", "a region ID", c.region_id)
   .yes_no("check_tags", c.check_tags)
   .choice("force", {"elastic", "total"}, force)
   .choice("fragment_density", {"true", "scaled"}, fragment_density)  // the order of FragmentDensity
   .yes_no("redraw", c.redraw)
   .choice("event_lists", {"insert", "rebuild"}, event_lists)
   .yes_no("check_lists", c.check_lists);
  t.parse(args);
  c.insert_lists = event_lists == 0;
  c.total_force = force == 1;
  c.fragment_density = static_cast<FragmentDensity>(fragment_density);
  c.seed = static_cast<std::uint64_t>(seed);
  c.every = static_cast<int>(every);
  c.random_orientation = orientation == 0;
  c.distribution = static_cast<StrengthDistribution>(distribution);
  c.layout = static_cast<FragmentLayout>(layout);
  return c;
}

namespace {
std::string number_text(double v)
{
  std::ostringstream out;
  out << v;
  return out.str();
}
}  // namespace

std::vector<std::string> suspicious_settings(const CrushSettings &c)
{
  std::vector<std::string> warnings;
  if (c.sigma_lim0 < 1e5)
    warnings.push_back("sigma_lim0 " + number_text(c.sigma_lim0) + " Pa is below 100 kPa, weaker than any grain "
                       "material: most grains break at their first contact (the paper's is 5e9 Pa; kPa given for Pa?)");
  if (c.cv > 2.0)
    warnings.push_back("cv above 2: most of the normal draw lies below zero and is clipped or truncated, so the "
                       "strengths no longer have the mean and spread asked for");
  if (c.weibull_m < 1.0 || c.weibull_m > 50.0)
    warnings.push_back("weibull_m outside [1, 50], the range measured on sand grains: the size effect "
                       "(d/(N d0))^(-3/m) is then extreme or absent");
  if (c.scale_factor < 1.0)
    warnings.push_back("scale below 1: the particles are smaller than the sand's (N is an upscaling factor)");
  if (c.fines_dimension < 2.0)
    warnings.push_back("fines_dimension below 2: crushed sands measure 2.5 to 2.9");
  if (c.rayleigh_fraction > 0.5)
    warnings.push_back("rayleigh_fraction above 0.5: the time-step check allows steps near the stability limit");
  return warnings;
}

}  // namespace crush

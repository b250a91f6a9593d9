/* Crushing model (plain C++): fix crush settings (see crush_settings.h). */
#include "crush_settings.h"

#include <set>

#include "crush_breakage_limit.h"
#include "crush_model_error.h"
#include "crush_number.h"

namespace crush {

namespace {

[[noreturn]] void fail(const std::string &keyword, const std::string &expected, const std::string &got)
{
  throw ModelError("fix crush: keyword '" + keyword + "' expects " + expected +
                   (got.empty() ? "" : ", got '" + got + "'"));
}

double number(const std::string &keyword, const std::string &text, const std::string &expected)
{
  return keyword_number("fix crush", keyword, text, expected);
}

bool yes_no(const std::string &keyword, const std::string &text)
{
  if (text == "yes") return true;
  if (text == "no") return false;
  fail(keyword, "'yes' or 'no'", text);
}

}  // namespace

double CrushSettings::size_scaled(double s, double d) const
{
  return size_effect ? size_scaled_strength(s, d, d0, weibull_m, scale_factor) : s;
}

CrushSettings parse_crush_settings(const std::vector<std::string> &args)
{
  CrushSettings c;
  std::set<std::string> seen;
  for (std::size_t k = 0; k < args.size(); k += 2) {
    const std::string &key = args[k];
    if (k + 1 >= args.size()) fail(key, "a value", "");
    const std::string &val = args[k + 1];
    seen.insert(key);
    if (key == "sigma_lim0") {
      c.sigma_lim0 = number(key, val, "a strength > 0 (Pa)");
      if (!(c.sigma_lim0 > 0.0)) fail(key, "a strength > 0 (Pa)", val);
    } else if (key == "cv") {
      c.cv = number(key, val, "a coefficient of variation >= 0");
      if (!(c.cv >= 0.0)) fail(key, "a coefficient of variation >= 0", val);
    } else if (key == "weibull_m") {
      c.weibull_m = number(key, val, "a Weibull modulus > 0");
      if (!(c.weibull_m > 0.0)) fail(key, "a Weibull modulus > 0", val);
    } else if (key == "d0") {
      c.d0 = number(key, val, "a reference diameter > 0 (m)");
      if (!(c.d0 > 0.0)) fail(key, "a reference diameter > 0 (m)", val);
    } else if (key == "seed") {
      const double s = number(key, val, "a positive integer");
      if (!(s >= 1.0) || s != static_cast<double>(static_cast<std::uint64_t>(s)))
        fail(key, "a positive integer", val);
      c.seed = static_cast<std::uint64_t>(s);
    } else if (key == "scale") {
      c.scale_factor = number(key, val, "an upscaling factor N > 0");
      if (!(c.scale_factor > 0.0)) fail(key, "an upscaling factor N > 0", val);
    } else if (key == "dmin") {
      c.dmin = number(key, val, "a diameter >= 0 (m)");
      if (!(c.dmin >= 0.0)) fail(key, "a diameter >= 0 (m)", val);
    } else if (key == "every") {
      const double e = number(key, val, "an integer >= 1");
      if (!(e >= 1.0) || e != static_cast<int>(e)) fail(key, "an integer >= 1", val);
      c.every = static_cast<int>(e);
    } else if (key == "orientation") {
      if (val == "random") c.random_orientation = true;
      else if (val == "fixed") c.random_orientation = false;
      else fail(key, "'random' or 'fixed'", val);
    } else if (key == "distribution") {
      if (val == "normal") c.distribution = StrengthDistribution::normal;
      else if (val == "normal_clipped") c.distribution = StrengthDistribution::normal_clipped;
      else if (val == "normal_clipped_originals") c.distribution = StrengthDistribution::normal_clipped_originals;
      else if (val == "weibull") c.distribution = StrengthDistribution::weibull;
      else if (val == "constant") c.distribution = StrengthDistribution::constant;
      else fail(key, "'normal', 'normal_clipped', 'normal_clipped_originals', 'weibull' or 'constant'", val);
    } else if (key == "size_effect") {
      c.size_effect = yes_no(key, val);
    } else if (key == "layout") {
      if (val == "fourteen") c.layout = FragmentLayout::fourteen;
      else if (val == "tetrahedral") c.layout = FragmentLayout::tetrahedral;
      else fail(key, "'fourteen' or 'tetrahedral'", val);
    } else if (key == "fines_dimension") {
      c.fines_dimension = number(key, val, "a fractal dimension < 3");
      if (!(c.fines_dimension < 3.0)) fail(key, "a fractal dimension < 3", val);
    } else if (key == "rayleigh_fraction") {
      c.rayleigh_fraction = number(key, val, "a fraction in (0, 1]");
      if (!(c.rayleigh_fraction > 0.0 && c.rayleigh_fraction <= 1.0)) fail(key, "a fraction in (0, 1]", val);
    } else if (key == "log") {
      c.log_file = val;
    } else if (key == "check_tags") {
      c.check_tags = yes_no(key, val);
    } else {
      throw ModelError("fix crush: unknown keyword '" + key +
                       "' (expected sigma_lim0, cv, weibull_m, d0, seed, scale, dmin, every, orientation, "
                       "distribution, size_effect, layout, fines_dimension, rayleigh_fraction, log or check_tags)");
    }
  }
  for (const char *required : {"sigma_lim0", "cv", "weibull_m", "d0", "seed"})
    if (!seen.count(required))
      throw ModelError(std::string("fix crush: keyword '") + required + "' is required");
  return c;
}

}  // namespace crush

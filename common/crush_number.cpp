/* Crushing model (plain C++): numbers given to the plugin's commands (see crush_number.h). */
#include "crush_number.h"

#include <cmath>
#include <cstdlib>

#include "crush_model_error.h"

namespace crush {

bool parse_finite(const std::string &text, double &value)
{
  char *end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) return false;
  value = v;
  return true;
}

double keyword_number(const std::string &command, const std::string &keyword, const std::string &text,
                      const std::string &expected)
{
  double value = 0.0;
  if (!parse_finite(text, value))
    throw ModelError(command + ": keyword '" + keyword + "' expects " + expected + ", got '" + text + "'");
  return value;
}

}  // namespace crush

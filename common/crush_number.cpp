/* Crushing model (plain C++): numbers given to the plugin's commands (see crush_number.h). */
#include "crush_number.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace crush {

bool parse_finite(const std::string &text, double &value)
{
  char *end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) return false;
  value = v;
  return true;
}

bool parse_whole(const std::string &text, long long &value)
{
  if (text.empty()) return false;
  char *end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (*end != '\0' || errno == ERANGE) return false;
  value = v;
  return true;
}

}  // namespace crush

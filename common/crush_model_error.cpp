/* Crushing model (plain C++): input validation shared by all model parts. */
#include "crush_model_error.h"

#include <sstream>

namespace crush {

void require(bool ok, const char *name, double value, const char *expected)
{
  if (ok) return;
  std::ostringstream msg;
  msg << name << " = " << value << ": expected " << expected;
  throw ModelError(msg.str());
}

}  // namespace crush

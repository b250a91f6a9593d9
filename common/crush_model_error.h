/* Crushing model (plain C++): the exception every model part throws on invalid input.
   Its message names the parameter and the allowed range, so that the LIGGGHTS adapters can pass it
   to error->all() unchanged. */
#ifndef CRUSH_MODEL_ERROR_H
#define CRUSH_MODEL_ERROR_H

#include <stdexcept>
#include <string>

namespace crush {

class ModelError : public std::invalid_argument {
 public:
  explicit ModelError(const std::string &what) : std::invalid_argument(what) {}
};

// Throws ModelError("<name> = <value>: expected <expected>") unless ok.
void require(bool ok, const char *name, double value, const char *expected);

}  // namespace crush

#endif

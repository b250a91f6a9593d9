/* Crushing model (plain C++): the one reader of numbers given to the plugin's commands (through
   crush_keywords.h).

   A keyword's value is accepted only when the whole text is a finite number: strtod alone would
   take "inf", "nan", "1e999" (overflow to inf) and "5x" (trailing text). */
#ifndef CRUSH_NUMBER_H
#define CRUSH_NUMBER_H

#include <string>

namespace crush {

// True, with value set, where text is a finite number in full.
bool parse_finite(const std::string &text, double &value);
// True, with value set, where text is a whole number (optionally signed) in full, within long long.
bool parse_whole(const std::string &text, long long &value);

}  // namespace crush

#endif

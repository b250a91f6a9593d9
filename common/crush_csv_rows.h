/* Crushing model (plain C++): CSV files whose rows start with their step (fix crush's event log,
   the decks' histories), cut back to a step when a run resumes from a checkpoint. */
#ifndef CRUSH_CSV_ROWS_H
#define CRUSH_CSV_ROWS_H

#include <string>

namespace crush {

// The text without the rows of steps after last_step: a row whose first field is a whole number is a
// step; rows of that step itself are kept unless drop_last_step. Other lines (the title) stay; a last
// line without its newline is a row cut short by a kill and goes. dropped: how many rows went.
std::string trim_rows(const std::string &csv, long long last_step, bool drop_last_step, int &dropped);

// The whole file as text; false (text untouched) where it cannot be opened.
bool read_text_file(const std::string &path, std::string &text);

}  // namespace crush

#endif

/* Crushing model (plain C++): see crush_csv_rows.h. */
#include "crush_csv_rows.h"

#include <fstream>
#include <sstream>

#include "crush_number.h"

namespace crush {

std::string trim_rows(const std::string &csv, long long last_step, bool drop_last_step, int &dropped)
{
  std::string out;
  dropped = 0;
  std::size_t at = 0;
  while (at < csv.size()) {
    std::size_t end = csv.find('\n', at);
    // a last line without its newline is a row cut short by the kill: dropped
    if (end == std::string::npos) {
      dropped++;
      break;
    }
    const std::string line = csv.substr(at, end - at);
    at = end + 1;
    long long step = 0;
    const bool is_row = parse_whole(line.substr(0, line.find(',')), step);
    if (is_row && (step > last_step || (drop_last_step && step == last_step))) {
      dropped++;
      continue;
    }
    out += line + "\n";
  }
  return out;
}

bool read_text_file(const std::string &path, std::string &text)
{
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream all;
  all << in.rdbuf();
  text = all.str();
  return true;
}

}  // namespace crush

/* Checkpoints (plain C++): see crush_checkpoint_files.h. */
#include "crush_checkpoint_files.h"

#include <sstream>

#include "crush_model_error.h"
#include "crush_number.h"

namespace crush {

std::string checkpoint_file(const std::string &base, int slot)
{
  return base + "." + std::to_string(slot) + ".restart";
}

std::string checkpoint_marker(const std::string &base)
{
  return base + ".last";
}

std::string format_marker(const std::vector<CheckpointEntry> &entries)
{
  std::ostringstream out;
  out << "# liggghts-crush checkpoint: step bytes file [variable=value ...], newest last\n";
  for (const CheckpointEntry &e : entries) {
    out << e.step << " " << e.bytes << " " << e.file;
    for (const auto &v : e.variables) out << " " << v.first << "=" << v.second;
    out << "\n";
  }
  return out.str();
}

std::vector<CheckpointEntry> parse_marker(const std::string &text)
{
  std::vector<CheckpointEntry> entries;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    number++;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string step, bytes, word;
    CheckpointEntry e;
    if (!(words >> step >> bytes >> e.file) || !parse_whole(step, e.step) || !parse_whole(bytes, e.bytes) ||
        e.step < 0 || e.bytes <= 0)
      throw ModelError("line " + std::to_string(number) + " '" + line + "' is not 'step bytes file'");
    while (words >> word) {
      const std::size_t eq = word.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == word.size())
        throw ModelError("line " + std::to_string(number) + ": '" + word + "' is not 'variable=value'");
      e.variables.emplace_back(word.substr(0, eq), word.substr(eq + 1));
    }
    entries.push_back(e);
  }
  return entries;
}

int next_slot(const std::string &base, const std::vector<CheckpointEntry> &entries)
{
  if (entries.empty()) return 1;
  return entries.back().file == checkpoint_file(base, 1) ? 2 : 1;
}

std::vector<CheckpointEntry> after_write(const std::string &base, const std::vector<CheckpointEntry> &entries,
                                         const CheckpointEntry &written)
{
  std::vector<CheckpointEntry> kept;
  for (int k = static_cast<int>(entries.size()) - 1; k >= 0; k--)
    if (entries[k].file != written.file &&
        (entries[k].file == checkpoint_file(base, 1) || entries[k].file == checkpoint_file(base, 2))) {
      kept.push_back(entries[k]);
      break;
    }
  kept.push_back(written);
  return kept;
}

}  // namespace crush

/* Checkpoints (plain C++): the bookkeeping of `checkpoint write|find|read` (checkpoint.h).

   A checkpoint BASE alternates between two restart files, BASE.1.restart and BASE.2.restart, so that
   a run killed while writing one still has the other. Each is written under a temporary name and
   renamed when complete; the marker BASE.last then records, newest last, each file's step, its size
   in bytes and the deck variables saved with it:

     # liggghts-crush checkpoint: step bytes file [variable=value ...], newest last
     20000 2811904 ckpt_O2.2.restart
     40000 2812416 ckpt_O2.1.restart H0=0.0039871 V0=6.2e-08

   A file is complete when it exists with the recorded size. Rows a killed run wrote after its last
   checkpoint are dropped from its CSV files by step (crush_csv_rows.h). */
#ifndef CRUSH_CHECKPOINT_FILES_H
#define CRUSH_CHECKPOINT_FILES_H

#include <string>
#include <utility>
#include <vector>

namespace crush {

struct CheckpointEntry {
  long long step = 0;
  long long bytes = 0;
  std::string file;
  std::vector<std::pair<std::string, std::string>> variables;  // name, value (as written)
};

// BASE.1.restart or BASE.2.restart (slot 1 or 2).
std::string checkpoint_file(const std::string &base, int slot);
std::string checkpoint_marker(const std::string &base);  // BASE.last

// The marker's text and back; parse_marker throws ModelError naming the line it cannot read.
std::string format_marker(const std::vector<CheckpointEntry> &entries);
std::vector<CheckpointEntry> parse_marker(const std::string &text);

// The slot the next checkpoint goes to: the one not holding the newest entry.
int next_slot(const std::string &base, const std::vector<CheckpointEntry> &entries);
// The entries after a checkpoint: the other slot's newest entry, if any, then the new one.
std::vector<CheckpointEntry> after_write(const std::string &base, const std::vector<CheckpointEntry> &entries,
                                         const CheckpointEntry &written);

// The newest entry whose file has the recorded size (size_of returns -1 for a missing file), or -1.
template <typename SizeOf>
int newest_complete(const std::vector<CheckpointEntry> &entries, SizeOf size_of)
{
  for (int k = static_cast<int>(entries.size()) - 1; k >= 0; k--)
    if (size_of(entries[k].file) == entries[k].bytes) return k;
  return -1;
}

}  // namespace crush

#endif

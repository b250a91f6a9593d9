/* ----------------------------------------------------------------------
   liggghts-crush: checkpoint, restart files a killed run resumes from. See doc/checkpoint.txt.

   checkpoint write BASE [variables v1 v2 ...]
     writes a restart file to BASE.1.restart or BASE.2.restart, alternately, under a temporary name
     renamed when complete, then the marker BASE.last (step, size, the named equal-style variables)
   checkpoint find BASE VAR
     sets the string variable VAR to the step of the newest complete checkpoint, or -1 if none
   checkpoint clear BASE
     removes BASE.last, BASE.1.restart and BASE.2.restart (a run that starts afresh)
   checkpoint read BASE [trim FILE TITLE ...]
     read_restart of the newest complete checkpoint, then the saved variables (equal style); each
     FILE (a CSV whose rows start with their step, TITLE its first line) loses the rows of steps
     after the checkpoint's
   Between two checkpoints a deck runs 'run N pre yes', so that the uninterrupted run and the resumed
   one start each stretch from the same full setup (doc/design.md, "Checkpoints").
------------------------------------------------------------------------- */
#ifdef COMMAND_CLASS

CommandStyle(checkpoint,Checkpoint)

#else

#ifndef LMP_CHECKPOINT_H
#define LMP_CHECKPOINT_H

#include <string>
#include <vector>

#include "crush_checkpoint_files.h"
#include "pointers.h"

namespace LAMMPS_NS {

class Checkpoint : protected Pointers {
 public:
  Checkpoint(class LAMMPS *);
  void command(int, char **);

 private:
  void write(const std::string &base, const std::vector<std::string> &variables);
  void find(const std::string &base, const std::string &var);
  void clear(const std::string &base);
  void read(const std::string &base, const std::vector<std::string> &trim);
  // The marker's entries and the newest complete one (-1: none), the same on every proc.
  std::vector<crush::CheckpointEntry> entries(const std::string &base, int &newest);
  void trim_file(const std::string &file, const std::string &title, long long step);
  void set_variable(const std::string &name, const char *style, const std::string &value);
  void report(const std::string &line);
  void fail(const std::string &what);  // error->all, naming the command
};

}  // namespace LAMMPS_NS

#endif
#endif

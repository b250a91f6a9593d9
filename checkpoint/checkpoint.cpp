/* ----------------------------------------------------------------------
   liggghts-crush: checkpoint (see checkpoint.h).
------------------------------------------------------------------------- */
#include "checkpoint.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <algorithm>

#include "comm.h"
#include "crush_csv_rows.h"
#include "crush_model_error.h"
#include "error.h"
#include "input.h"
#include "read_restart.h"
#include "update.h"
#include "variable.h"
#include "write_restart.h"

using namespace LAMMPS_NS;

namespace {

long long file_size(const std::string &file)
{
  struct stat st;
  return stat(file.c_str(), &st) == 0 ? static_cast<long long>(st.st_size) : -1;
}

// Written under FILE.tmp, flushed to the disk, then renamed: FILE is always complete or absent.
bool write_text_atomically(const std::string &file, const std::string &text)
{
  const std::string tmp = file + ".tmp";
  FILE *fp = fopen(tmp.c_str(), "w");
  if (!fp) return false;
  const bool ok = fwrite(text.data(), 1, text.size(), fp) == text.size() && fflush(fp) == 0 &&
                  fsync(fileno(fp)) == 0;
  return fclose(fp) == 0 && ok && rename(tmp.c_str(), file.c_str()) == 0;
}

bool sync_file(const std::string &file)
{
  const int fd = open(file.c_str(), O_RDONLY);
  if (fd < 0) return false;
  const bool ok = fsync(fd) == 0;
  return close(fd) == 0 && ok;
}

void broadcast(std::string &text, MPI_Comm world)
{
  int n = static_cast<int>(text.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  text.resize(n);
  if (n > 0) MPI_Bcast(&text[0], n, MPI_CHAR, 0, world);
}

}  // namespace

Checkpoint::Checkpoint(LAMMPS *lmp) : Pointers(lmp) {}

void Checkpoint::command(int narg, char **arg)
{
  const std::vector<std::string> args(arg, arg + narg);
  if (args.size() < 2) fail("expected 'checkpoint write|find|read BASE ...'");
  const std::string &base = args[1];
  if (base.find_first_of("*%") != std::string::npos)
    fail("BASE '" + base + "' may not contain '*' or '%' (it names two files of its own)");
  if (args[0] == "write") {
    if (args.size() > 2 && args[2] != "variables") fail("write: unknown keyword '" + args[2] + "' (expected 'variables')");
    write(base, std::vector<std::string>(args.begin() + std::min<std::size_t>(3, args.size()), args.end()));
  } else if (args[0] == "clear") {
    if (args.size() != 2) fail("expected 'checkpoint clear BASE'");
    clear(base);
  } else if (args[0] == "find") {
    if (args.size() != 3) fail("expected 'checkpoint find BASE VAR'");
    find(base, args[2]);
  } else if (args[0] == "read") {
    if (args.size() > 2 && args[2] != "trim") fail("read: unknown keyword '" + args[2] + "' (expected 'trim')");
    const std::vector<std::string> trim(args.begin() + std::min<std::size_t>(3, args.size()), args.end());
    if (trim.size() % 2 != 0) fail("read: 'trim' expects pairs 'file title' (the title: the file's first line)");
    read(base, trim);
  } else {
    fail("unknown action '" + args[0] + "' (expected write, find, read or clear)");
  }
}

void Checkpoint::fail(const std::string &what)
{
  error->all(FLERR, ("checkpoint: " + what).c_str());
}

std::vector<crush::CheckpointEntry> Checkpoint::entries(const std::string &base, int &newest)
{
  std::string text;
  int present = 0;
  if (comm->me == 0) present = crush::read_text_file(crush::checkpoint_marker(base), text) ? 1 : 0;
  MPI_Bcast(&present, 1, MPI_INT, 0, world);
  newest = -1;
  if (!present) return {};
  broadcast(text, world);
  std::vector<crush::CheckpointEntry> list;
  try {
    list = crush::parse_marker(text);
  } catch (const crush::ModelError &e) {
    fail("the marker " + crush::checkpoint_marker(base) + " is not a checkpoint marker: " + e.what());
  }
  if (comm->me == 0) newest = crush::newest_complete(list, file_size);
  MPI_Bcast(&newest, 1, MPI_INT, 0, world);
  return list;
}

void Checkpoint::write(const std::string &base, const std::vector<std::string> &variables)
{
  int newest = -1;
  const std::vector<crush::CheckpointEntry> list = entries(base, newest);
  crush::CheckpointEntry entry;
  entry.step = static_cast<long long>(update->ntimestep);
  entry.file = crush::checkpoint_file(base, crush::next_slot(base, list));
  for (const std::string &name : variables) {
    const int ivar = input->variable->find(const_cast<char *>(name.c_str()));
    if (ivar < 0 || !input->variable->equalstyle(ivar))
      fail("write: 'variables " + name + "': no equal-style variable of that name");
    char value[64];
    snprintf(value, sizeof(value), "%.17g", input->variable->compute_equal(ivar));
    entry.variables.emplace_back(name, value);
  }
  const double start = MPI_Wtime();
  const std::string tmp = entry.file + ".tmp";
  WriteRestart writer(lmp);
  char *wargs[1] = {const_cast<char *>(tmp.c_str())};
  writer.command(1, wargs);
  int ok = 1;
  if (comm->me == 0) {
    entry.bytes = file_size(tmp);
    ok = entry.bytes > 0 && sync_file(tmp) && rename(tmp.c_str(), entry.file.c_str()) == 0 &&
         write_text_atomically(crush::checkpoint_marker(base), crush::format_marker(crush::after_write(base, list, entry)));
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, world);
  if (!ok) fail("write: could not write " + entry.file + " or " + crush::checkpoint_marker(base) + " (disk full? permissions?)");
  char line[512];
  snprintf(line, sizeof(line), "CHECKPOINT step %lld: %s (%.1f MB, %.2f s)", entry.step, entry.file.c_str(),
           entry.bytes / 1e6, MPI_Wtime() - start);
  report(line);
}

// A run that starts afresh removes the checkpoints of an earlier run under the same name: a later
// resume must never fall back on another run's state.
void Checkpoint::clear(const std::string &base)
{
  if (comm->me != 0) return;
  int removed = 0;
  for (const std::string &file : {crush::checkpoint_marker(base), crush::checkpoint_file(base, 1), crush::checkpoint_file(base, 2)})
    if (std::remove(file.c_str()) == 0) removed++;
  if (removed > 0) report("CHECKPOINT " + base + ": the earlier run's checkpoints removed (a new run starts)");
}

void Checkpoint::find(const std::string &base, const std::string &var)
{
  int newest = -1;
  const std::vector<crush::CheckpointEntry> list = entries(base, newest);
  set_variable(var, "string", newest < 0 ? "-1" : std::to_string(list[newest].step));
}

void Checkpoint::read(const std::string &base, const std::vector<std::string> &trim)
{
  int newest = -1;
  const std::vector<crush::CheckpointEntry> list = entries(base, newest);
  if (newest < 0)
    fail("read: no complete checkpoint " + crush::checkpoint_file(base, 1) + " or " + crush::checkpoint_file(base, 2) +
         (list.empty() ? " (no marker " + crush::checkpoint_marker(base) + ")" : " of the sizes its marker records") +
         ": nothing to resume; run without resuming");
  const crush::CheckpointEntry &entry = list[newest];
  if (newest + 1 < static_cast<int>(list.size()) && comm->me == 0) {
    const std::string msg = "checkpoint: the newest checkpoint " + list.back().file +
                            " is incomplete; resuming from the one before, " + entry.file;
    error->warning(FLERR, msg.c_str());
  }
  ReadRestart reader(lmp);
  char *rargs[1] = {const_cast<char *>(entry.file.c_str())};
  reader.command(1, rargs);
  if (static_cast<long long>(update->ntimestep) != entry.step)
    fail("read: " + entry.file + " holds step " + std::to_string(update->ntimestep) + ", its marker says " +
         std::to_string(entry.step));
  for (const auto &v : entry.variables) set_variable(v.first, "equal", v.second);
  for (std::size_t k = 0; k + 1 < trim.size(); k += 2) trim_file(trim[k], trim[k + 1], entry.step);
  report("CHECKPOINT resumed from " + entry.file + " at step " + std::to_string(entry.step));
}

// Rows after the checkpoint's step go (the killed run wrote them after it). A file left without its
// title (killed before its first row reached the disk) gets it back, so the resumed run appends.
void Checkpoint::trim_file(const std::string &file, const std::string &title, long long step)
{
  int ok = 1, dropped = 0;
  if (comm->me == 0) {
    std::string text;
    crush::read_text_file(file, text);
    std::string kept = crush::trim_rows(text, step, false, dropped);
    if (kept.compare(0, title.size() + 1, title + "\n") != 0) kept = title + "\n" + kept;
    ok = write_text_atomically(file, kept);
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, world);
  if (!ok) fail("read: could not rewrite 'trim " + file + "'");
  report("CHECKPOINT " + file + ": " + std::to_string(dropped) + " rows after step " + std::to_string(step) + " dropped");
}

// One line on the screen and in the log, from proc 0.
void Checkpoint::report(const std::string &line)
{
  if (comm->me != 0) return;
  if (screen) fprintf(screen, "%s\n", line.c_str());
  if (logfile) fprintf(logfile, "%s\n", line.c_str());
}

void Checkpoint::set_variable(const std::string &name, const char *style, const std::string &value)
{
  char *vargs[3] = {const_cast<char *>(name.c_str()), const_cast<char *>(style), const_cast<char *>(value.c_str())};
  input->variable->set(3, vargs);
}

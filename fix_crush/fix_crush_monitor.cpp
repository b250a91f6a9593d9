/* liggghts-crush: the link between the contact models and fix crush (see fix_crush_monitor.h). */
#include "fix_crush_monitor.h"

#include <map>

namespace LAMMPS_NS {

int CrushMonitor::generation = 0;

namespace {
std::map<LAMMPS *, const CrushRecorder *> &recorders()
{
  static std::map<LAMMPS *, const CrushRecorder *> instance;
  return instance;
}
}  // namespace

void CrushMonitor::attach(LAMMPS *lmp, const CrushRecorder *recorder)
{
  if (recorder) recorders()[lmp] = recorder;
  else recorders().erase(lmp);
  ++generation;
}

void CrushMonitor::resolve()
{
  const std::map<LAMMPS *, const CrushRecorder *>::const_iterator it = recorders().find(lmp_);
  recorder_ = it == recorders().end() ? 0 : it->second;
  generation_ = generation;
}

}  // namespace LAMMPS_NS

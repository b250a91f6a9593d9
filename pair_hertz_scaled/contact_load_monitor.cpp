/* liggghts-crush: how the contact models publish each contact's load (see contact_load_monitor.h). */
#include "contact_load_monitor.h"

#include <map>

namespace LAMMPS_NS {

int ContactLoadMonitor::generation = 0;

namespace {
std::map<LAMMPS *, const ContactLoadRecorder *> &recorders()
{
  static std::map<LAMMPS *, const ContactLoadRecorder *> instance;
  return instance;
}
}  // namespace

void ContactLoadMonitor::attach(LAMMPS *lmp, const ContactLoadRecorder *recorder)
{
  if (recorder) recorders()[lmp] = recorder;
  else recorders().erase(lmp);
  ++generation;
}

void ContactLoadMonitor::resolve()
{
  const std::map<LAMMPS *, const ContactLoadRecorder *>::const_iterator it = recorders().find(lmp_);
  recorder_ = it == recorders().end() ? 0 : it->second;
  generation_ = generation;
}

}  // namespace LAMMPS_NS

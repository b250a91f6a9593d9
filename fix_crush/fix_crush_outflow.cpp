/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's books for the particles that leave the box (see fix_crush.h and
   doc/fix_crush.txt).

   LIGGGHTS writes outflow as a fixed boundary: an exchange drops every particle beyond it, and
   'thermo_modify lost' says whether that is allowed (ignore, the default; warn) or stops the run
   (error). Before each exchange (setup's and the reneighboring steps') the fix counts the particles
   that this exchange will drop: their volume leaves the books as outflow (f_crush[6], their number
   f_crush[7]), so that particles + removed volume + outflow stays the volume of the grains.
   A shrink-wrapped boundary ('s', 'm') grows with its particles before the exchange: nothing beyond
   it is dropped.
------------------------------------------------------------------------- */
#include "fix_crush.h"

#include <cstdio>

#include "atom.h"
#include "comm.h"
#include "crush_constants.h"
#include "domain.h"
#include "error.h"
#include "output.h"
#include "thermo.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
const int kFixedBoundary = 1;  // domain->boundary: 0 periodic, 1 fixed, 2 shrink-wrapped, 3 shrink with a minimum
}  // namespace

// Comm::exchange keeps a particle on the processor whose sub-domain holds it, lo <= x < hi: beyond a
// fixed face of the box no processor does.
bool FixCrush::leaves_box(const double *x) const
{
  for (int d = 0; d < 3; d++) {
    if (domain->boundary[d][0] == kFixedBoundary && !(x[d] >= domain->boxlo[d])) return true;
    if (domain->boundary[d][1] == kFixedBoundary && !(x[d] < domain->boxhi[d])) return true;
  }
  return false;
}

// One reduction per exchange: the particles that it will drop, and their volume.
void FixCrush::count_outflow()
{
  if (domain->nonperiodic == 0) return;
  double local[2] = {0.0, 0.0};
  for (int i = 0; i < atom->nlocal; i++)
    if (leaves_box(atom->x[i])) {
      local[0] += 1.0;
      local[1] += crush::sphere_volume(2.0 * atom->radius[i]);
    }
  double sums[2];
  MPI_Allreduce(local, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  if (sums[0] == 0.0) return;
  const bigint count = static_cast<bigint>(sums[0]);
  if (output->thermo->lost_policy() == Thermo::LOST_ERROR) {
    char msg[320];
    snprintf(msg, sizeof(msg), "fix crush: " BIGINT_FORMAT " particles leave the box at step " BIGINT_FORMAT
             " and 'thermo_modify lost error' forbids it: keep them inside, or allow it with 'thermo_modify lost "
             "ignore' (fix crush then counts their volume as outflow, f_crush[6])", count, update->ntimestep);
    error->all(FLERR, msg);
  }
  outflow_particles_ += count;
  outflow_volume_ += sums[1];
  particle_count_ -= count;
  report_outflow(count, sums[1]);
}

// Once a run: the log says that particles leave, and where the books keep them.
void FixCrush::report_outflow(bigint count, double volume)
{
  if (outflow_reported_) return;
  outflow_reported_ = true;
  if (comm->me != 0) return;
  char msg[400];
  snprintf(msg, sizeof(msg), "fix crush: " BIGINT_FORMAT " particles (%g m^3) leave the box at step " BIGINT_FORMAT
           " ('thermo_modify lost %s'): their volume leaves the books as outflow, f_crush[6] (the particles "
           "f_crush[7]); later ones are counted without a message\n",
           count, volume, update->ntimestep,
           output->thermo->lost_policy() == Thermo::LOST_WARN ? "warn" : "ignore");
  if (screen) fputs(msg, screen);
  if (logfile) fputs(msg, logfile);
}

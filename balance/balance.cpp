/* ----------------------------------------------------------------------
   liggghts-crush: balance (see balance.h).
------------------------------------------------------------------------- */
#include "balance.h"

#include <cstdio>

#include "atom.h"
#include "balance_cuts.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "update.h"

using namespace LAMMPS_NS;

Balance::Balance(LAMMPS *lmp) : Pointers(lmp) {}

void Balance::fail(const std::string &what) const
{
  error->all(FLERR, ("balance: " + what).c_str());
}

void Balance::command(int narg, char **arg)
{
  if (domain->box_exist == 0) fail("the box must exist first");
  BalanceCuts cuts(lmp, "balance", narg, arg);
  const BalanceCuts::Outcome out = cuts.balance();
  if (!out.moved.empty()) migrate();
  const std::string line = "BALANCE: " + cuts.describe(out);
  if (comm->me == 0 && screen) fprintf(screen, "%s\n", line.c_str());
  if (comm->me == 0 && logfile) fprintf(logfile, "%s\n", line.c_str());
}

// The atoms go to their new processors now (one hop: crush_shift_cuts.h) and the tag map follows;
// the next run rebuilds everything else (ghosts, neighbour lists, meshes, fixes' per-atom data) in a
// full setup. Nothing here needs the neighbour settings, which a restart read just before leaves unset.
void Balance::migrate()
{
  const bigint natoms = atom->natoms;
  domain->pbc();
  domain->reset_box();
  comm->exchange();
  if (atom->map_style) {
    atom->map_init();
    atom->map_set();
  }
  bigint nlocal = atom->nlocal, total = 0;
  MPI_Allreduce(&nlocal, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (total != natoms) {
    char msg[160];
    snprintf(msg, sizeof(msg), "particles were lost while they moved to their new processors (" BIGINT_FORMAT
             " of " BIGINT_FORMAT " kept)", total, natoms);
    fail(msg);
  }
  update->first_update = 0;  // the next run, 'pre no' too, starts with lmp->init() and a full setup
}

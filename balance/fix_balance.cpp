/* ----------------------------------------------------------------------
   liggghts-crush: fix balance (see fix_balance.h).
------------------------------------------------------------------------- */
#include "fix_balance.h"

#include <cstdio>
#include <cstring>
#include <string>

#include "balance_cuts.h"
#include "comm.h"
#include "crush_number.h"
#include "domain.h"
#include "error.h"
#include "neighbor.h"
#include "lmptype.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixBalance::FixBalance(LAMMPS *lmp, int narg, char **arg) :
  Fix(lmp, narg, arg), every_(0), now_(1.0), before_(1.0), after_(1.0), moves_(0), checks_(0),
  out_(NULL)
{
  const std::string who = std::string("fix balance (id ") + id + ")";
  long long every = 0;
  if (narg < 4 || !crush::parse_whole(arg[3], every) || every < 1 || every > 1000000000)
    error->all(FLERR, (who + ": Nevery expects a whole number of steps >= 1, got '" + (narg < 4 ? "" : arg[3]) +
                       "' (fix ID group balance Nevery thresh shift dimstr niter stopthresh [weight neighbors])")
                          .c_str());
  every_ = static_cast<int>(every);
  int nsettings = narg - 4;
  if (nsettings >= 2 && strcmp(arg[narg - 2], "out") == 0) {
    nsettings -= 2;
    if (comm->me == 0) {
      out_ = fopen(arg[narg - 1], "w");
      if (!out_) error->one(FLERR, (who + ": cannot open the out file '" + arg[narg - 1] + "'").c_str());
      fprintf(out_, "# fix balance (id %s): one line a move of the planes\n", id);
    }
  }
  cuts_.reset(new BalanceCuts(lmp, who, nsettings, arg + 4));
  force_reneighbor = 1;
  next_reneighbor = -1;
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 4;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
}

FixBalance::~FixBalance()
{
  if (out_) fclose(out_);
}

int FixBalance::setmask()
{
  return PRE_EXCHANGE;
}

void FixBalance::init()
{
  if (domain->triclinic) error->fix_error(FLERR, this, "a triclinic box is not supported");
}

// A run's setup (Verlet::setup), write_restart and write_data call this, then set up the communication
// and exchange the particles themselves.
void FixBalance::setup_pre_exchange()
{
  rebalance();
  schedule();
}

// A checked step forces a rebuild (next_reneighbor), so this runs on it; the exchange that follows
// moves the particles to the new planes.
void FixBalance::pre_exchange()
{
  if (update->ntimestep < next_reneighbor) return;
  // The step's exchange and ghosts need the new sub-domains; Verlet redoes this itself only when the
  // box changes.
  if (rebalance()) {
    domain->set_local_box();
    comm->setup();
    if (neighbor->style) neighbor->setup_bins();
  }
  schedule();
}

// Whether the planes moved.
bool FixBalance::rebalance()
{
  // the particles in the box, the box around the particles (shrink-wrapped): the cuts are fractions of it
  domain->pbc();
  domain->reset_box();
  const BalanceCuts::Outcome out = cuts_->balance();
  checks_++;
  now_ = out.after;
  if (out.moved.empty()) return false;
  before_ = out.before;
  after_ = out.after;
  moves_++;
  if (out_) {
    fprintf(out_, "step " BIGINT_FORMAT ": %s\n", update->ntimestep, cuts_->describe(out).c_str());
    fflush(out_);
  }
  return true;
}

void FixBalance::schedule()
{
  next_reneighbor = (update->ntimestep / every_) * every_ + every_;
}

double FixBalance::compute_scalar()
{
  return now_;
}

double FixBalance::compute_vector(int n)
{
  switch (n) {
    case 0: return before_;
    case 1: return after_;
    case 2: return static_cast<double>(moves_);
    default: return static_cast<double>(checks_);
  }
}

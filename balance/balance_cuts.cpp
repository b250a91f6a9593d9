/* ----------------------------------------------------------------------
   liggghts-crush: the planes between processors by weight (see balance_cuts.h).
------------------------------------------------------------------------- */
#include "balance_cuts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <unordered_map>

#include "atom.h"
#include "comm.h"
#include "crush_model_error.h"
#include "crush_number.h"
#include "crush_shift_cuts.h"
#include "domain.h"
#include "error.h"
#include "neighbor.h"

using namespace LAMMPS_NS;

namespace {

// A number of the command line (crush_number.h: all of the word, finite); ok also needs v >= least.
double number(const char *word, double least, bool &ok)
{
  double v = 0.0;
  ok = crush::parse_finite(word, v) && v >= least;
  return v;
}

}  // namespace

BalanceCuts::BalanceCuts(LAMMPS *lmp, const std::string &who, int narg, char **arg) : Pointers(lmp), who_(who)
{
  if ((narg != 5 && narg != 7) || strcmp(arg[1], "shift") != 0)
    fail("expected 'thresh shift dimstr niter stopthresh [weight neighbors]' (e.g. '1.05 shift x 20 1.02')");
  if (narg == 7 && (strcmp(arg[5], "weight") != 0 || strcmp(arg[6], "neighbors") != 0))
    fail(std::string("expected 'weight neighbors' after stopthresh, got '") + arg[5] + " " + arg[6] + "'");
  by_work_ = narg == 7;
  bool ok = false;
  thresh_ = number(arg[0], 1.0, ok);
  if (!ok) fail(std::string("thresh expects a number >= 1 (the largest count over the mean), got '") + arg[0] + "'");
  axes_ = arg[2];
  for (std::size_t k = 0; k < axes_.size(); k++)
    if (!strchr("xyz", axes_[k]) || axes_.find(axes_[k]) != k || (axes_[k] == 'z' && domain->dimension == 2))
      fail("dimstr expects the axes x, y, z (each once, z in 3d only), got '" + axes_ + "'");
  if (axes_.empty()) fail("dimstr expects at least one axis");
  long long halvings = 0;
  if (!crush::parse_whole(arg[3], halvings) || halvings < 1 || halvings > 60)
    fail(std::string("niter expects a whole number in [1, 60] (bisection steps per cut), got '") + arg[3] + "'");
  halvings_ = static_cast<int>(halvings);
  stop_ = number(arg[4], 1.0, ok);
  if (!ok) fail(std::string("stopthresh expects a number >= 1, got '") + arg[4] + "'");
  if (domain->triclinic) fail("a triclinic box is not supported");
}

void BalanceCuts::fail(const std::string &what) const
{
  error->all(FLERR, (who_ + ": " + what).c_str());
}

double BalanceCuts::imbalance()
{
  find_weights();
  return crush::imbalance(counts_per_processor());
}

BalanceCuts::Outcome BalanceCuts::balance()
{
  Outcome out;
  out.before = out.after = imbalance();
  if (out.before <= thresh_) return out;
  // the planes as they are: a grid of more than one axis can end fuller somewhere than it began
  std::vector<std::vector<double>> old(3);
  for (int d = 0; d < 3; d++) old[d].assign(split(d), split(d) + comm->procgrid[d] + 1);
  const int uniform = comm->uniform;
  for (char axis : axes_) {
    const int dim = axis - 'x';
    if (comm->procgrid[dim] < 2) continue;
    shift(dim);
    out.moved += axis;
    out.after = crush::imbalance(counts_per_processor());
    if (out.after <= stop_) break;
  }
  if (out.after >= out.before) {
    for (int d = 0; d < 3; d++) std::copy(old[d].begin(), old[d].end(), split(d));
    comm->uniform = uniform;
    out.after = out.before;
    out.moved.clear();
  }
  return out;
}

// Each local particle's weight: 1, or with 'weight neighbors' 1 + its neighbours, the particles (own
// or ghost) closer than r_i + r_j + skin: the pairs the granular lists hold, which the pair loop
// works through. A pair of two local particles counts for both, a pair with a ghost (computed on
// both processors, newton off) for the local one on each: a processor's weights sum to its
// particles + 2 x its own pairs + its pairs across. Counted from the current positions on a grid of
// cells (not from the lists, whose indices an exchange or a replacement leaves stale). Ghosts are
// current after a run, a checkpoint or a step's forward communication, and absent after
// read_restart, an exchange or fix crush's replacement: then the pairs across processors go
// uncounted, a small part of the work.
void BalanceCuts::find_weights()
{
  const int nlocal = atom->nlocal;
  weight_.assign(nlocal, 1.0);
  if (by_work_) count_neighbours();
  double local = 0.0;
  for (double w : weight_) local += w;
  MPI_Allreduce(&local, &total_weight_, 1, MPI_DOUBLE, MPI_SUM, world);
}

// weight_[i] += the particles closer than r_i + r_j + skin, each local i against local and ghosts.
void BalanceCuts::count_neighbours()
{
  const int nlocal = atom->nlocal, nall = atom->nlocal + atom->nghost;
  const double *const *x = atom->x;
  const double *radius = atom->radius;
  const double skin = neighbor->skin;
  double rmax = 0.0;
  for (int i = 0; i < nall; i++) rmax = std::max(rmax, radius[i]);
  const double cell = std::max(2.0 * rmax + skin, 1e-300);
  auto index = [&](const double *p, int d) { return static_cast<long long>(std::floor((p[d] - domain->boxlo[d]) / cell)); };
  auto key = [](long long a, long long b, long long c) { return ((a + (1 << 20)) << 42) | ((b + (1 << 20)) << 21) | (c + (1 << 20)); };
  std::unordered_map<long long, std::vector<int>> cells;
  for (int j = 0; j < nall; j++) cells[key(index(x[j], 0), index(x[j], 1), index(x[j], 2))].push_back(j);
  for (int i = 0; i < nlocal; i++) {
    const long long a = index(x[i], 0), b = index(x[i], 1), c = index(x[i], 2);
    for (long long da = -1; da <= 1; da++)
      for (long long db = -1; db <= 1; db++)
        for (long long dc = -1; dc <= 1; dc++) {
          const auto found = cells.find(key(a + da, b + db, c + dc));
          if (found == cells.end()) continue;
          for (int j : found->second) {
            if (j == i) continue;
            const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
            const double reach = radius[i] + radius[j] + skin;
            if (dx * dx + dy * dy + dz * dz < reach * reach) weight_[i] += 1.0;
          }
        }
  }
}

double *BalanceCuts::split(int dim) const
{
  return dim == 0 ? comm->xsplit : (dim == 1 ? comm->ysplit : comm->zsplit);
}

// The weights below each cut (a fraction of the box along dim), summed over all processors.
std::vector<double> BalanceCuts::counts_below(int dim, const std::vector<double> &cuts) const
{
  std::vector<double> local(cuts.size(), 0.0), all(cuts.size(), 0.0);
  const double lo = domain->boxlo[dim], length = domain->prd[dim];
  for (int i = 0; i < atom->nlocal; i++) {
    const double f = (atom->x[i][dim] - lo) / length;
    for (std::size_t k = 0; k < cuts.size(); k++)
      if (f < cuts[k]) local[k] += weight_[i];
  }
  MPI_Allreduce(local.data(), all.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_SUM, world);
  return all;
}

// The weight each processor would own with the current cuts: one sum per processor.
std::vector<double> BalanceCuts::counts_per_processor() const
{
  std::vector<double> local(comm->nprocs, 0.0), all(comm->nprocs, 0.0);
  for (int i = 0; i < atom->nlocal; i++) {
    int loc[3] = {0, 0, 0};
    for (int d = 0; d < domain->dimension; d++) {
      const double f = (atom->x[i][d] - domain->boxlo[d]) / domain->prd[d];
      const double *s = split(d);
      while (loc[d] + 1 < comm->procgrid[d] && f >= s[loc[d] + 1]) loc[d]++;
    }
    local[comm->grid2proc[loc[0]][loc[1]][loc[2]]] += weight_[i];
  }
  MPI_Allreduce(local.data(), all.data(), comm->nprocs, MPI_DOUBLE, MPI_SUM, world);
  return all;
}

void BalanceCuts::shift(int dim)
{
  double *s = split(dim);
  const int slabs = comm->procgrid[dim];
  const std::vector<double> old(s, s + slabs + 1);
  // a slab at least as wide as the ghost cutoff (at most half the mean width)
  const double width = std::min(comm->cutghostuser > 0.0 ? comm->cutghostuser : neighbor->cutneighmax,
                                0.5 * domain->prd[dim] / slabs) / domain->prd[dim];
  try {
    const std::vector<double> cuts = crush::shift_cuts(
        old, total_weight_, halvings_, width, [this, dim](const std::vector<double> &c) { return counts_below(dim, c); });
    for (int k = 1; k < slabs; k++) s[k] = cuts[k];
  } catch (const crush::ModelError &e) {
    fail(e.what());
  }
  comm->uniform = 0;
}

std::string BalanceCuts::describe(const Outcome &out) const
{
  char line[512];
  int n = snprintf(line, sizeof(line), "imbalance %.4f -> %.4f (largest %s over the mean)", out.before, out.after,
                   by_work_ ? "work, particles + neighbour pairs," : "count");
  for (int d = 0; d < domain->dimension; d++) {
    if (comm->procgrid[d] < 2) continue;
    n += snprintf(line + n, sizeof(line) - n, ", %c cuts", 'x' + d);
    for (int k = 1; k < comm->procgrid[d] && n < 400; k++) n += snprintf(line + n, sizeof(line) - n, " %.6g", split(d)[k]);
  }
  if (out.moved.empty()) snprintf(line + n, sizeof(line) - n, " (unchanged)");
  return line;
}

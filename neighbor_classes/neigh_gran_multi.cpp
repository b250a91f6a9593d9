/* Granular neighbour lists in style multi (newton off): the pairs of granular_bin_no_newton, found
   by size class (crush_size_classes.h), with the contact history carried over as the bin build
   carries it. */
#include "neigh_gran_multi.h"

#include <cstring>
#include <string>
#include <vector>

#include "atom.h"
#include "crush_number.h"
#include "error.h"
#include "fix_contact_history.h"
#include "lammps.h"
#include "my_page.h"
#include "neigh_list.h"
#include "neighbor.h"

using namespace LAMMPS_NS;

int NeighSizeClasses::parse(LAMMPS *lmp, int narg, char **arg)
{
  const std::string expected = "expected 'auto' or N followed by N increasing upper radii (m) of the classes";
  auto fail = [&](const std::string &what) {
    lmp->error->all(FLERR, ("neigh_modify size_classes: " + what).c_str());
  };
  if (narg < 1) fail(expected);
  if (strcmp(arg[0], "auto") == 0) {
    bounds.set_auto();
    return 1;
  }
  long long n = 0;
  if (!crush::parse_whole(arg[0], n) || n < 1) fail(expected + ", got '" + arg[0] + "'");
  if (narg < n + 1) fail(expected + ": " + arg[0] + " bounds announced, " + std::to_string(narg - 1) + " given");
  std::vector<double> upper(n);
  for (int k = 0; k < n; k++)
    if (!crush::parse_finite(arg[k + 1], upper[k])) fail(expected + ", got '" + arg[k + 1] + "' as a bound");
  const std::string wrong = bounds.set_upper(upper);
  if (!wrong.empty()) fail(wrong + " (" + expected + ")");
  return static_cast<int>(n) + 1;
}

void Neighbor::granular_multi_no_newton(NeighList *list)
{
  // fix neighlist/mesh reads the main bins after the pair lists are built
  bin_atoms();

  double **x = atom->x;
  double *radius = atom->radius;
  int *tag = atom->tag;
  int *type = atom->type;
  int *mask = atom->mask;
  int *molecule = atom->molecule;
  const int nall = atom->nlocal + atom->nghost;
  const int nlocal = includegroup ? atom->nfirst : atom->nlocal;

  crush::SizeClassBins &classes = size_classes->bins;
  classes.build(size_classes->bounds, x, radius, nall, contactDistanceFactor, skin);
  classes.collect_reverse(nlocal);

  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  MyPage<int> *ipage = list->ipage;

  FixContactHistory *fix_history = list->fix_history;
  int *npartner = NULL, **partner = NULL;
  double **contacthistory = NULL;
  int **first_contact_flag = NULL;
  double **first_contact_hist = NULL;
  MyPage<int> *ipage_contact_flag = NULL;
  MyPage<double> *dpage_contact_hist = NULL;
  int dnum = 0;
  if (fix_history) {
    npartner = fix_history->npartner_;
    partner = fix_history->partner_;
    contacthistory = fix_history->contacthistory_;
    first_contact_flag = list->listgranhistory->firstneigh;
    first_contact_hist = list->listgranhistory->firstdouble;
    ipage_contact_flag = list->listgranhistory->ipage;
    dpage_contact_hist = list->listgranhistory->dpage;
    dnum = list->listgranhistory->dnum;
  }

  int inum = 0;
  ipage->reset();
  if (fix_history) {
    ipage_contact_flag->reset();
    dpage_contact_hist->reset();
  }

  for (int i = 0; i < nlocal; i++) {
    int n = 0, nn = 0;
    int *neighptr = ipage->vget();
    int *contact_flag_ptr = NULL;
    double *contact_hist_ptr = NULL;
    if (fix_history) {
      contact_flag_ptr = ipage_contact_flag->vget();
      contact_hist_ptr = dpage_contact_hist->vget();
      if (!contact_flag_ptr || !contact_hist_ptr)
        error->one(FLERR, "Neighbor list overflow, boost neigh_modify one");
    }
    const double radi = radius[i];

    classes.for_each_neighbor(i, [&](int j, double rsq) {
      if (exclude && exclusion(i, j, type[i], type[j], mask, molecule)) return;
      neighptr[n] = j;
      if (fix_history) {
        // a touching pair takes up its stored history, any other starts from zero
        const double radsum = (radi + radius[j]) * contactDistanceFactor;
        int m = npartner[i];
        if (rsq < radsum * radsum)
          for (m = 0; m < npartner[i]; m++)
            if (partner[i][m] == tag[j]) break;
        const bool stored = m < npartner[i];
        contact_flag_ptr[n] = stored ? 1 : 0;
        for (int d = 0; d < dnum; d++) contact_hist_ptr[nn++] = stored ? contacthistory[i][m * dnum + d] : 0.0;
      }
      n++;
    });

    ilist[inum++] = i;
    firstneigh[i] = neighptr;
    numneigh[i] = n;
    ipage->vgot(n);
    if (ipage->status()) error->one(FLERR, "Neighbor list overflow, boost neigh_modify one");
    if (fix_history) {
      first_contact_flag[i] = contact_flag_ptr;
      first_contact_hist[i] = contact_hist_ptr;
      ipage_contact_flag->vgot(n);
      dpage_contact_hist->vgot(nn);
    }
  }
  list->inum = inum;
}

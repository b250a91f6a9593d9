/* ----------------------------------------------------------------------
   liggghts-crush: the fragments of one event still apart before they first interact
   (see fix_crush_family_check.h).
------------------------------------------------------------------------- */
#include "fix_crush_family_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "update.h"

using namespace LAMMPS_NS;

void CrushFamilyCheck::remember(const std::vector<tagint> &mothers, tagint first, int nfrag)
{
  for (std::size_t k = 0; k < mothers.size(); k++)
    families_.push_back({mothers[k], first + nfrag * static_cast<tagint>(k), nfrag, update->ntimestep});
}

void CrushFamilyCheck::check(const char *crush_id, bool setup)
{
  // At a step's pre_force, fragments replaced in this step's pre_exchange lie where they were put.
  if (families_.empty()) return;  // the same on every processor: all remember every family
  const bigint now = update->ntimestep;
  const bool moved = setup || std::any_of(families_.begin(), families_.end(),
                                          [now](const Family &f) { return f.step < now; });
  if (!moved) return;
  std::vector<Fragment> fragments = gather();
  std::sort(fragments.begin(), fragments.end(), [](const Fragment &a, const Fragment &b) { return a.tag < b.tag; });
  for (std::size_t a = 0; a < fragments.size(); a++) {
    const Family *family = family_of(static_cast<tagint>(fragments[a].tag));
    for (std::size_t b = a + 1; b < fragments.size() && fragments[b].tag < family->first + family->nfrag; b++) {
      double dx = fragments[b].x[0] - fragments[a].x[0], dy = fragments[b].x[1] - fragments[a].x[1],
             dz = fragments[b].x[2] - fragments[a].x[2];
      domain->minimum_image(dx, dy, dz);
      const double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
      if (distance < std::min(fragments[a].radius, fragments[b].radius))
        report(crush_id, *family, fragments[a], fragments[b], distance);
    }
  }
  families_.erase(std::remove_if(families_.begin(), families_.end(), [now](const Family &f) { return f.step < now; }),
                  families_.end());
}

// The remembered fragments that still exist, from every processor (tag, radius, position).
std::vector<CrushFamilyCheck::Fragment> CrushFamilyCheck::gather() const
{
  std::vector<Fragment> mine;
  for (int i = 0; i < atom->nlocal; i++)
    if (family_of(atom->tag[i]))
      mine.push_back({static_cast<double>(atom->tag[i]), atom->radius[i], {atom->x[i][0], atom->x[i][1], atom->x[i][2]}});
  const int per = sizeof(Fragment) / sizeof(double);
  const int count = static_cast<int>(mine.size()) * per;
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (int p = 0; p < comm->nprocs; p++) {
    displs[p] = total;
    total += counts[p];
  }
  std::vector<Fragment> all(total / per);
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, world);
  return all;
}

// The family holding fragment tag, or NULL. Families are remembered in the order of their tags
// (new tags follow every tag ever given): a binary search.
const CrushFamilyCheck::Family *CrushFamilyCheck::family_of(tagint tag) const
{
  auto after = std::upper_bound(families_.begin(), families_.end(), tag,
                                [](tagint t, const Family &family) { return t < family.first; });
  if (after == families_.begin()) return NULL;
  const Family &family = *(after - 1);
  return tag < family.first + family.nfrag ? &family : NULL;
}

void CrushFamilyCheck::report(const char *crush_id, const Family &family, const Fragment &a, const Fragment &b,
                              double distance) const
{
  char msg[700];
  snprintf(msg, sizeof(msg), "Fix crush (id %s): fragments %.0f and %.0f of grain %ld (replaced at step " BIGINT_FORMAT
           ") lie %g m apart at step " BIGINT_FORMAT ", less than the smaller one's radius %g m: another fix moved "
           "them after the replacement (a fix that sets positions from per-atom data the fragments copied); "
           "doc/fix_crush.txt lists how each LIGGGHTS fix treats fragments", crush_id, a.tag, b.tag,
           static_cast<long>(family.mother), family.step, distance, update->ntimestep,
           std::min(a.radius, b.radius));
  error->all(FLERR, msg);
}

/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's fragments added to the neighbour lists without a rebuild (see
   fix_crush_list_insertion.h).
------------------------------------------------------------------------- */
#include "fix_crush_list_insertion.h"

#include <algorithm>
#include <cstdio>
#include <typeinfo>
#include <unordered_set>

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "compute.h"
#include "fix.h"
#include "fix_contact_history_mesh.h"
#include "fix_mesh_surface.h"
#include "fix_neighlist_mesh.h"
#include "fix_property_atom.h"
#include "fix_wall_gran.h"
#include "modify.h"
#include "my_page.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "primitive_wall.h"
#include "tri_mesh.h"

using namespace LAMMPS_NS;

namespace {

// LIGGGHTS asks for its granular lists with half = 0: each pair is stored once all the same
bool is_granular_half_list(const NeighRequest *req)
{
  return req->gran && !req->full && !req->ghost && !req->copy && !req->skip && !req->half_from_full &&
         !req->respainner && !req->respamiddle && !req->respaouter;
}

}  // namespace

// Who asked for a list: the fix or compute by style and ID, or the pair style.
std::string CrushListInsertion::requester(const NeighRequest *req) const
{
  for (int k = 0; k < modify->nfix; k++)
    if (req->requestor == modify->fix[k]) return std::string("fix ") + modify->fix[k]->style + " " + modify->fix[k]->id;
  for (int k = 0; k < modify->ncompute; k++)
    if (req->requestor == modify->compute[k])
      return std::string("compute ") + modify->compute[k]->style + " " + modify->compute[k]->id;
  return req->pair ? "the pair style" : "a command";
}

std::string CrushListInsertion::unsupported_reason()
{
  list_ = NULL;
  if (neighbor->includegroup) return "neigh_modify include builds the lists for a group only";
  if (!neighbor->dist_check) return "neigh_modify check no: the lists are rebuilt on schedule, not by distance";
  if (domain->triclinic) return "the box is triclinic";
  for (int i = 0; i < neighbor->nlist && i < neighbor->old_nrequest; i++) {
    const NeighRequest *req = neighbor->old_requests[i];  // this run's requests, kept after init
    if (req->occasional || req->granhistory) continue;  // built on demand; filled with its granular list
    if (!is_granular_half_list(req)) return "a neighbour list other than the granular pair list is kept, by " + requester(req);
    if (list_) return "more than one granular neighbour list is kept";
    list_ = neighbor->lists[i];
  }
  if (!list_) return "there is no granular pair list";
  // Fixes that act at a build keep per-particle indices of their own; the walls' lists are extended
  // here: a primitive wall's (extend_wall_lists), a mesh's and its contact history (extend_mesh_lists).
  for (int k = 0; k < modify->nfix; k++) {
    if (!(modify->fmask[k] & FixConst::PRE_NEIGHBOR)) continue;
    Fix *fix = modify->fix[k];
    if (dynamic_cast<FixWallGran *>(fix) || dynamic_cast<FixNeighlistMesh *>(fix) ||
        typeid(*fix) == typeid(FixContactHistoryMesh))
      continue;
    return std::string("fix ") + fix->style + " keeps lists of its own between builds";
  }
  return std::string();
}

bool CrushListInsertion::can_take(const std::vector<int> &mothers) const
{
  if (!list_) return false;
  std::vector<char> sent(atom->nlocal);
  comm->mark_sent(sent.data(), atom->nlocal);
  for (int m : mothers)
    if (sent[m]) return false;
  return true;
}

bool CrushListInsertion::inside_subdomain(const std::vector<int> &mothers) const
{
  double **x = atom->x;
  const double *radius = atom->radius;
  for (int m : mothers)
    for (int d = 0; d < 3; d++)
      if (x[m][d] - radius[m] < domain->sublo[d] || x[m][d] + radius[m] >= domain->subhi[d]) return false;
  return true;
}

void CrushListInsertion::open(const std::vector<int> &mothers, int nfrag)
{
  nlocal_before_ = atom->nlocal;
  shift_ = (nfrag - 1) * static_cast<int>(mothers.size());
  families_.assign(mothers.size(), Family());
  family_of_.assign(nlocal_before_, -1);
  double **xhold = neighbor->hold_positions();
  for (std::size_t k = 0; k < mothers.size(); k++) {
    Family &f = families_[k];
    f.mother = mothers[k];
    for (int d = 0; d < 3; d++) {
      f.x_mother[d] = atom->x[f.mother][d];
      f.hold_mother[d] = xhold[f.mother][d];
    }
    family_of_[f.mother] = static_cast<int>(k);
  }
  read_neighbours();
  // room for the new owned particles in the lists and the build's positions, and for the ghosts behind them
  const int nlocal_after = nlocal_before_ + shift_;
  list_->grow_keeping(nlocal_after);
  if (list_->listgranhistory) list_->listgranhistory->grow_keeping(nlocal_after);
  neighbor->grow_hold(nlocal_after);
  const int nghost = atom->nghost;
  while (atom->nmax < nlocal_before_ + shift_ + 1 + nghost) atom->avec->grow(0);
  move_ghosts(nlocal_before_, nlocal_before_ + shift_ + 1);
}

// One pass over the list: each mother's partners (both directions of the half list), her entries'
// contact histories cleared (her slot's fragment touches nothing yet), and every ghost index moved
// up by the slots the fragments will take.
void CrushListInsertion::read_neighbours()
{
  NeighList *history = list_->listgranhistory;
  const int dnum = history ? history->dnum : 0;
  for (int ii = 0; ii < list_->inum; ii++) {
    const int i = list_->ilist[ii];
    int *jlist = list_->firstneigh[i];
    const int fi = family_of_[i];
    for (int jj = 0; jj < list_->numneigh[i]; jj++) {
      if (jlist[jj] >= nlocal_before_) {
        jlist[jj] += shift_;
        if (fi >= 0) families_[fi].neighbours.push_back(jlist[jj]);
        else continue;
      } else {
        const int j = jlist[jj], fj = family_of_[j];
        if (fi < 0 && fj < 0) continue;
        if (fi >= 0) families_[fi].neighbours.push_back(j);
        if (fj >= 0) families_[fj].neighbours.push_back(i);
      }
      if (history) {
        history->firstneigh[i][jj] = 0;
        std::fill(history->firstdouble[i] + jj * dnum, history->firstdouble[i] + (jj + 1) * dnum, 0.0);
      }
    }
  }
}

// The ghosts' block of per-atom data, from slot 'from' to slot 'to' (every per-atom array, the fixes' too).
void CrushListInsertion::move_ghosts(int from, int to)
{
  const int nghost = atom->nghost;
  if (to > from)
    for (int k = nghost - 1; k >= 0; k--) atom->avec->copy(from + k, to + k, 0);
  else
    for (int k = 0; k < nghost; k++) atom->avec->copy(from + k, to + k, 0);
}

void CrushListInsertion::add_family(int mother, int first_new, int count)
{
  Family &f = families_[family_of_[mother]];
  f.members.assign(1, mother);
  for (int k = 0; k < count; k++) f.members.push_back(first_new + k);
}

void CrushListInsertion::close()
{
  move_ghosts(nlocal_before_ + shift_ + 1, nlocal_before_ + shift_);
  comm->shift_ghosts(nlocal_before_, shift_);
  std::vector<int> pairs;
  for (const Family &f : families_)
    for (std::size_t m = 1; m < f.members.size(); m++) {
      pairs.clear();
      add_pairs(f, f.members[m], pairs);
      append_list(f.members[m], pairs);
    }
  set_hold_positions();
  extend_wall_lists();
  extend_mesh_lists();
  atom->map_init();  // collective: the new tags lie beyond the map (replace_mothers runs on every processor)
  atom->map_set();
}

// A new slot's pairs, each stored once: against every particle of the old numbering (the mother's
// partners, the mother's own slot and other mothers' slots) under the new slot, and between two new
// slots under the lower one. A pair is kept while the two can still touch before the next build:
// both moved less than half the skin from where the last build saw them (the fragment: its mother),
// so a pair farther apart now than the contact distance plus twice the skin never touches.
void CrushListInsertion::add_pairs(const Family &family, int member, std::vector<int> &pairs) const
{
  auto consider = [&](int b) {
    if (b != member && near(member, b)) pairs.push_back(b);
  };
  auto consider_family = [&](const Family &f) {
    for (int b : f.members)
      if (b == f.mother || b > member) consider(b);
  };
  consider_family(family);
  for (int j : family.neighbours) {
    if (j < nlocal_before_ && family_of_[j] >= 0) consider_family(families_[family_of_[j]]);
    else consider(j);
  }
}

bool CrushListInsertion::near(int i, int j) const
{
  double **x = atom->x;
  const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
  const double cut = (atom->radius[i] + atom->radius[j]) * neighbor->contactDistanceFactor + 2.0 * neighbor->skin;
  return dx * dx + dy * dy + dz * dz < cut * cut;
}

void CrushListInsertion::append_list(int i, const std::vector<int> &pairs)
{
  const int n = static_cast<int>(pairs.size());
  if (n > list_->oneatom) error->one(FLERR, "Neighbor list overflow, boost neigh_modify one");
  int *neighptr = list_->ipage->vget();
  std::copy(pairs.begin(), pairs.end(), neighptr);
  list_->ipage->vgot(n);
  if (list_->ipage->status()) error->one(FLERR, "Neighbor list overflow, boost neigh_modify one");
  list_->firstneigh[i] = neighptr;
  list_->numneigh[i] = n;
  list_->ilist[list_->inum++] = i;
  NeighList *history = list_->listgranhistory;
  if (!history) return;
  const int dnum = history->dnum;
  int *touch = history->ipage->vget();
  std::fill(touch, touch + n, 0);
  history->ipage->vgot(n);
  double *values = history->dpage->vget();
  std::fill(values, values + n * dnum, 0.0);
  history->dpage->vgot(n * dnum);
  if (history->ipage->status() || history->dpage->status())
    error->one(FLERR, "Neighbor list overflow, boost neigh_modify one");
  history->firstneigh[i] = touch;
  history->firstdouble[i] = values;
}

// A fragment's position at the last build is taken as its mother's, shifted by its offset: its
// displacement since then is hers, and the distance check watches it from there.
void CrushListInsertion::set_hold_positions()
{
  double **xhold = neighbor->hold_positions();
  double *rhold = neighbor->hold_radii();
  for (const Family &f : families_)
    for (int b : f.members) {
      for (int d = 0; d < 3; d++) xhold[b][d] = f.hold_mother[d] + (atom->x[b][d] - f.x_mother[d]);
      if (rhold) rhold[b] = atom->radius[b];
    }
}

// A fragment is no nearer a wall than its mother's surface: it joins a primitive wall's list where she was.
void CrushListInsertion::extend_wall_lists()
{
  for (int k = 0; k < modify->nfix; k++) {
    FixWallGran *fix = dynamic_cast<FixWallGran *>(modify->fix[k]);
    PrimitiveWall *wall = fix ? fix->primitiveWall() : NULL;
    if (!wall) continue;
    int *listed = NULL;
    const int n = wall->getNeighbors(listed);
    std::vector<int> added;
    for (int k2 = 0; k2 < n; k2++)
      if (listed[k2] < nlocal_before_ && family_of_[listed[k2]] >= 0) {
        const Family &f = families_[family_of_[listed[k2]]];
        added.insert(added.end(), f.members.begin() + 1, f.members.end());
      }
    for (int a : added) wall->addNeighbor(a);
  }
}

// The same for each mesh: a fragment joins the triangles' lists where its mother was (the periodic
// ghosts' indices there move up with the others), and every fragment, the one in her slot too,
// starts without mesh contacts.
void CrushListInsertion::extend_mesh_lists()
{
  for (FixMeshSurface *mesh : meshes_with_lists()) {
    FixNeighlistMesh *lists = mesh->meshNeighlist();
    // each fragment's count of triangles that list it (n_neighs_mesh_*, fragments start at 0): the
    // mesh contact history sizes its slots by it
    FixPropertyAtom *count = lists->fix_nneighs();
    int added = 0;
    for (int t = 0; t < lists->n_triangle_lists(); t++) {
      std::vector<int> &listed = lists->contact_list(t);
      const std::size_t n = listed.size();
      for (std::size_t e = 0; e < n; e++) {
        if (listed[e] >= nlocal_before_) {
          listed[e] += shift_;
        } else if (family_of_[listed[e]] >= 0) {
          const Family &f = families_[family_of_[listed[e]]];
          listed.insert(listed.end(), f.members.begin() + 1, f.members.end());
          added += static_cast<int>(f.members.size()) - 1;
          for (int b : f.members) count->set_vector_atom_int(b, count->get_vector_atom_int(b) + 1);
        }
      }
    }
    lists->contacts_added(added);
    FixContactHistoryMesh *history = mesh->contactHistory();
    if (!history) continue;
    for (const Family &f : families_)
      for (int b : f.members) history->clear_contacts(b);
  }
}

// The mesh walls' meshes that keep particle lists (those a fix wall/gran uses).
std::vector<FixMeshSurface *> CrushListInsertion::meshes_with_lists() const
{
  std::vector<FixMeshSurface *> meshes;
  for (int k = 0; k < modify->nfix; k++) {
    FixMeshSurface *mesh = dynamic_cast<FixMeshSurface *>(modify->fix[k]);
    if (mesh && mesh->meshNeighlist()) meshes.push_back(mesh);
  }
  return meshes;
}

void CrushListInsertion::verify() const
{
  verify_pairs();
  verify_mesh_lists();
}

// Every pair of touching particles (owned with owned or ghost) is in the list: sorted by x, each
// particle is compared with those within the largest contact distance along x.
void CrushListInsertion::verify_pairs() const
{
  if (!list_) return;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  double **x = atom->x;
  const double *radius = atom->radius;
  std::unordered_set<long long> listed;
  auto key = [nall](int i, int j) { return static_cast<long long>(std::min(i, j)) * nall + std::max(i, j); };
  for (int ii = 0; ii < list_->inum; ii++) {
    const int i = list_->ilist[ii];
    for (int jj = 0; jj < list_->numneigh[i]; jj++) listed.insert(key(i, list_->firstneigh[i][jj] & NEIGHMASK));
  }
  std::vector<int> order(nall);
  double rmax = 0.0;
  for (int i = 0; i < nall; i++) {
    order[i] = i;
    rmax = std::max(rmax, radius[i]);
  }
  std::sort(order.begin(), order.end(), [x](int a, int b) { return x[a][0] < x[b][0]; });
  const double cdf = neighbor->contactDistanceFactor;
  for (std::size_t a = 0; a < order.size(); a++) {
    const int i = order[a];
    for (std::size_t b = a + 1; b < order.size() && x[order[b]][0] - x[i][0] < 2.0 * rmax * cdf; b++) {
      const int j = order[b];
      if (i >= nlocal && j >= nlocal) continue;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double touch = (radius[i] + radius[j]) * cdf;
      if (dx * dx + dy * dy + dz * dz >= touch * touch || listed.count(key(i, j))) continue;
      char msg[256];
      snprintf(msg, sizeof(msg), "fix crush (check_lists): particles %d and %d touch but are not in the neighbour list",
               atom->tag[i], atom->tag[j]);
      error->one(FLERR, msg);
    }
  }
}

// Every owned particle of a mesh wall's group that touches a triangle (as fix wall/gran resolves the
// contact) is in that triangle's list.
void CrushListInsertion::verify_mesh_lists() const
{
  const double reach = neighbor->contactDistanceFactor - 1.0;
  for (FixMeshSurface *mesh : meshes_with_lists()) {
    FixNeighlistMesh *lists = mesh->meshNeighlist();
    TriMesh *triangles = mesh->triMesh();
    const int ntri = triangles->sizeLocal() + triangles->sizeGhost();
    for (int t = 0; t < ntri && t < lists->n_triangle_lists(); t++) {
      const std::vector<int> &listed = lists->contact_list(t);
      const std::unordered_set<int> in_list(listed.begin(), listed.end());
      for (int i = 0; i < atom->nlocal; i++) {
        if (!(atom->mask[i] & lists->groupbit_wall_mesh) || in_list.count(i)) continue;
        double delta[3], bary[3];
        int barysign;
        const double deltan = triangles->resolveTriSphereContactBary(i, t, atom->radius[i], atom->x[i], delta, bary,
                                                                     barysign, true);
        if (deltan > 0.0 && deltan >= reach * atom->radius[i]) continue;
        char msg[256];
        snprintf(msg, sizeof(msg), "fix crush (check_lists): particle %d touches triangle %d of mesh %s but is not "
                 "in its list", atom->tag[i], triangles->id(t), mesh->id);
        error->one(FLERR, msg);
      }
    }
  }
}

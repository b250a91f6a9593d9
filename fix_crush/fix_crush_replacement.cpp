/* ----------------------------------------------------------------------
   liggghts-crush: fix crush's replacement of a mother by its fragments (see fix_crush.h and
   doc/fix_crush.txt): the fragments, what they inherit, and the books that prove every event was
   replaced exactly once.

   A fragment is a piece of its mother: it takes her type, group, velocity, spin, image and density
   (with 'fragment_density scaled' raised by (R/r)^2, crush_fragment_density.h; its true density kept),
   and the values of every fix property/atom that describe the material's state (temperature, a
   user's own properties), copied. Values that sum over a particle (heat flux and source, CFD drag)
   go by the fragment's mass share, so that the fragments hold what the mother held less the removed
   volume's share. Contacts are new: contact histories (fix contact/history, the primitive walls'
   history_<wall>) start empty. What fixes that drive, hold or anchor grains keep for a fragment
   (insert/stream, spring/self, move, rigid bodies) is fix_crush_driven_grains.h's.
------------------------------------------------------------------------- */
#include "fix_crush.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "crush_constants.h"
#include "crush_fragment_density.h"
#include "crush_fragments.h"
#include "fix_crush_list_insertion.h"
#include "crush_model_error.h"
#include "domain.h"
#include "error.h"
#include "fix_crush_driven_grains.h"
#include "fix_crush_family_check.h"
#include "fix_property_atom.h"
#include "group.h"
#include "irregular.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {

// Per-particle values that sum something (a power, a force): split by mass share.
const char *const kSharedProperties[] = {"heatFlux", "heatSource", "directionalHeatFlux", "dragforce", "hdtorque",
                                        "Ksl", "KslRotation", "KslExtra"};

bool is_shared(const char *name)
{
  for (const char *shared : kSharedProperties)
    if (strcmp(name, shared) == 0) return true;
  return false;
}

}  // namespace

// At init: every fix property/atom but fix crush's own, with its rule. A primitive wall keeps its
// contact history in 'history_<wall ID>' (fix wall/gran), a mesh its count of triangles listing a
// particle in 'n_neighs_mesh_<mesh>' (its contact history reads that many slots): a fragment's wall
// contacts are new, the count set where it joins a list (fix_crush_list_insertion.cpp). A
// driving fix's data (insert/stream's release) keep their defaults: the fragment is not driven.
// The other per-atom arrays without defaults for a new atom (fix store, store/state, ave/atom,
// spring/self: LIGGGHTS leaves the slot as it was) are copied, never left stale.
void FixCrush::find_inherited_state()
{
  inherited_.clear();
  copied_arrays_.clear();
  std::vector<std::string> wall_histories;
  for (int k = 0; k < modify->nfix; k++)
    if (strcmp(modify->fix[k]->style, "wall/gran") == 0)
      for (const char *prefix : {"history_", "force_"})
        wall_histories.push_back(prefix + std::string(modify->fix[k]->id));
  for (int k = 0; k < modify->nfix; k++) {
    FixPropertyAtom *fix = dynamic_cast<FixPropertyAtom *>(modify->fix[k]);
    if (!fix || fix == fix_data_ || fix == fix_true_density_) continue;
    const std::string name = fix->id;
    Inheritance rule = Inheritance::COPY;
    if (std::find(wall_histories.begin(), wall_histories.end(), name) != wall_histories.end() ||
        name.compare(0, 14, "n_neighs_mesh_") == 0 || driven_->driving_property(fix))
      rule = Inheritance::NEW;
    else if (is_shared(fix->id))
      rule = Inheritance::SHARE;
    inherited_.push_back({fix, rule});
  }
  for (int k = 0; k < atom->nextra_grow; k++) {
    Fix *fix = modify->fix[atom->extra_grow[k]];
    if (!fix->create_attribute && !dynamic_cast<FixPropertyAtom *>(fix)) copied_arrays_.push_back(fix);
  }
}

// The fragment's per-atom values from its mother's, after every fix's set_arrays gave it the defaults.
void FixCrush::inherit_state(int mother, int fragment, double mass_share) const
{
  for (Fix *fix : copied_arrays_) fix->copy_arrays(mother, fragment, 0);
  for (const InheritedState &state : inherited_) {
    if (state.rule == Inheritance::NEW) continue;
    FixPropertyAtom *fix = state.fix;
    fix->copy_arrays(mother, fragment, 0);
    if (state.rule != Inheritance::SHARE) continue;
    if (fix->array_atom)
      for (int k = 0; k < fix->get_nvalues(); k++) fix->array_atom[fragment][k] *= mass_share;
    else
      fix->vector_atom[fragment] *= mass_share;
  }
}

// in_place: the mothers lie away from every boundary, and the fragments join the lists without a
// rebuild (fix_crush_list_insertion.h); otherwise the rebuild that follows builds the lists, after the
// fragments migrated.
void FixCrush::replace_mothers(bool in_place)
{
  // New tags follow every tag in use (and every tag ever given), in the agreed event order.
  const tagint first = std::max(largest_tag() + 1, next_tag_);
  if (static_cast<bigint>(first) + static_cast<bigint>(nfrag_) * static_cast<bigint>(pending_.size()) > MAXTAGINT)
    error->all(FLERR, "fix crush: particle tags would exceed the largest tag LIGGGHTS allows (MAXTAGINT)");
  log_events(pending_, first);

  const std::vector<std::pair<std::size_t, int>> owned = owned_mothers();
  const int nlocal_before = atom->nlocal;
  double removed_local = 0.0, smallest = 0.0;
  if (in_place) {
    replace_in_place(owned, first, removed_local, smallest);
  } else {
    std::vector<int> mothers;
    for (const auto &event : owned) {
      mothers.push_back(event.second);
      removed_local += replace_one(event, first, smallest);
    }
    delete_mothers(mothers);
  }

  // Books: the volume that left the particles is the removed volume, nothing else; and every
  // event replaced exactly once, counted on all processors (one reduction per event step).
  double local_sums[3] = {removed_local, static_cast<double>(atom->nlocal - nlocal_before),
                          static_cast<double>(owned.size())};
  double sums[3];
  MPI_Allreduce(local_sums, sums, 3, MPI_DOUBLE, MPI_SUM, world);
  removed_volume_ += sums[0];
  double smallest_all = 0.0, big = smallest > 0.0 ? smallest : 1e300;
  MPI_Allreduce(&big, &smallest_all, 1, MPI_DOUBLE, MPI_MIN, world);
  if (smallest_all < 1e300)
    smallest_fragment_size_ = smallest_fragment_size_ == 0.0 ? smallest_all : std::min(smallest_fragment_size_, smallest_all);
  events_total_ += static_cast<bigint>(pending_.size());
  particle_count_ += static_cast<bigint>(nfrag_ - 1) * static_cast<bigint>(pending_.size());
  check_books(sums[1], sums[2]);
  next_tag_ = first + nfrag_ * static_cast<tagint>(pending_.size());
  atom->natoms += static_cast<bigint>(nfrag_ - 1) * static_cast<bigint>(pending_.size());

  if (in_place) {
    refresh_needed_ = true;  // new local atoms: this step's per-atom work is redone (pre_force)
  } else {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
    // Fragments may lie outside this sub-domain or the periodic box: remap and migrate them.
    domain->pbc();
    domain->reset_box();
    if (irregular_->migrate_check()) irregular_->migrate_atoms();
  }
  if (settings_.check_tags) check_unique_tags();
  remember_families(first);

  if (settings_.dmin <= 0.0) check_time_step(smallest_radius());
}

// Every agreed event's fragments, for the check before they first interact (fix_crush_family_check.h).
void FixCrush::remember_families(tagint first) const
{
  std::vector<tagint> mothers;
  for (const Event &event : pending_) mothers.push_back(event.tag);
  family_check_->remember(mothers, first, nfrag_);
}

// One event's fragments appended; returns the volume they leave out, and lowers 'smallest' to the
// smallest fragment's sand size, d / N with the mother's N (read before she is replaced).
double FixCrush::replace_one(const std::pair<std::size_t, int> &event, tagint first, double &smallest)
{
  const std::size_t k = event.first;
  const int i = event.second;
  const double d = crush::smallest_fragment_ratio(settings_.layout) * pending_[k].diameter / scale_of(i);
  smallest = smallest == 0.0 ? d : std::min(smallest, d);
  return create_fragments(i, first + nfrag_ * static_cast<tagint>(k), pending_[k].generation + 1);
}

// Each mother's fragments appended over the slots the ghosts left, the last moved into her slot at
// once, so that no other index moves; then the lists learn the new slots.
void FixCrush::replace_in_place(const std::vector<std::pair<std::size_t, int>> &owned, tagint first,
                                double &removed, double &smallest)
{
  std::vector<int> mothers;
  for (const auto &event : owned) mothers.push_back(event.second);
  list_insertion_->open(mothers, nfrag_);
  for (const auto &event : owned) {
    const int first_new = atom->nlocal;
    removed += replace_one(event, first, smallest);
    atom->avec->copy(atom->nlocal - 1, event.second, 1);
    atom->nlocal--;
    list_insertion_->add_family(event.second, first_new, nfrag_ - 1);
  }
  list_insertion_->close();
}

// The agreed events whose mother this processor owns, as (event, local index), all resolved before
// the first fragment exists. create_atom() appends at nlocal, over the ghost slots, while the atom
// map still points into them: once fragments are appended, a mother that is only a ghost here maps
// to an index below the grown nlocal and would be taken as owned, and its fragments created twice.
std::vector<std::pair<std::size_t, int>> FixCrush::owned_mothers() const
{
  std::vector<std::pair<std::size_t, int>> owned;
  const int nlocal = atom->nlocal;
  for (std::size_t k = 0; k < pending_.size(); k++) {
    const int i = atom->map(pending_[k].tag);
    if (i >= 0 && i < nlocal) owned.emplace_back(k, i);  // else a ghost, or owned by another processor
  }
  return owned;
}

// Always on: each event replaced by exactly one processor, and (fragments - 1) new particles per
// event. A failure names both numbers and stops the run before a corrupted state is written.
void FixCrush::check_books(double added, double replaced) const
{
  const double events = static_cast<double>(pending_.size());
  if (replaced == events && added == (nfrag_ - 1) * events) return;
  char msg[400];
  snprintf(msg, sizeof(msg), "fix crush: at step " BIGINT_FORMAT " %.0f mothers were replaced and %.0f particles "
           "added, the books require %.0f and %.0f: particles were lost or duplicated (please report this with "
           "the deck)", update->ntimestep, replaced, added, events, (nfrag_ - 1) * events);
  error->all(FLERR, msg);
}

// The largest tag in use on all processors (0 without particles).
tagint FixCrush::largest_tag() const
{
  int largest = 0, largest_all = 0;  // LIGGGHTS 3.8.0 stores tags as int (atom->tag)
  for (int i = 0; i < atom->nlocal; i++) largest = std::max(largest, atom->tag[i]);
  MPI_Allreduce(&largest, &largest_all, 1, MPI_INT, MPI_MAX, world);
  return largest_all;
}

// With 'check_tags yes' (tests): every tag in use exactly once over all processors.
void FixCrush::check_unique_tags() const
{
  const tagint maxtag_all = largest_tag();
  std::vector<int> seen(maxtag_all + 1, 0), seen_all(maxtag_all + 1, 0);
  for (int i = 0; i < atom->nlocal; i++) seen[atom->tag[i]]++;
  MPI_Allreduce(seen.data(), seen_all.data(), maxtag_all + 1, MPI_INT, MPI_SUM, world);
  for (tagint t = 0; t <= maxtag_all; t++)
    if (seen_all[t] > 1) {
      char msg[200];
      snprintf(msg, sizeof(msg), "fix crush (check_tags): tag %d is held by %d particles at step " BIGINT_FORMAT,
               t, seen_all[t], update->ntimestep);
      error->all(FLERR, msg);
    }
}

// Appends the mother's fragments (the mother is deleted afterwards) and returns the volume they leave out (m^3).
double FixCrush::create_fragments(int mother, tagint first_tag, int generation)
{
  // Copy the mother: creating atoms may reallocate every per-atom array.
  const int type = atom->type[mother], mask = atom->mask[mother], tag = atom->tag[mother];
  const tagint image = atom->image[mother];
  const double R = atom->radius[mother], density = atom->density[mother], rho_true = true_density(mother);
  double xm[3], vm[3], wm[3];
  for (int k = 0; k < 3; k++) {
    xm[k] = atom->x[mother][k];
    vm[k] = atom->v[mother][k];
    wm[k] = atom->omega[mother][k];
  }
  if (const char *refusing = driven_->refusing_fix(mother)) driven_->refuse(id, tag, refusing);
  std::vector<crush::Fragment> fragments;
  try {
    fragments = crush::fragment_layout(settings_.layout, R);
  } catch (const crush::ModelError &e) {
    particle_error(tag, R, density, "replacing it by fragments", e);
  }
  double removed = crush::sphere_volume(2.0 * R);
  if (settings_.random_orientation)
    fragments = crush::rotated(fragments, crush::random_rotation(settings_.seed, static_cast<std::uint64_t>(tag)));

  for (std::size_t f = 0; f < fragments.size(); f++) {
    double coord[3];
    for (int k = 0; k < 3; k++) coord[k] = xm[k] + fragments[f].offset[k];
    atom->avec->create_atom(type, coord);
    const int n = atom->nlocal - 1;
    const double r = fragments[f].radius;
    atom->tag[n] = first_tag + static_cast<tagint>(f);
    atom->mask[n] = mask;
    atom->image[n] = image;
    atom->radius[n] = r;
    atom->density[n] = crush::fragment_density(settings_.fragment_density, density, R, r);
    const double volume = crush::sphere_volume(2.0 * r);
    removed -= volume;
    atom->rmass[n] = atom->density[n] * volume;
    for (int k = 0; k < 3; k++) {
      atom->v[n][k] = vm[k];
      atom->omega[n][k] = wm[k];
    }
    for (int m = 0; m < modify->nfix; m++)
      if (modify->fix[m]->create_attribute) {
        modify->fix[m]->pre_set_arrays();  // as LIGGGHTS' own creators do: defaults may name a property
        modify->fix[m]->set_arrays(n);
      }
    inherit_state(mother, n, volume / crush::sphere_volume(2.0 * R));
    driven_->anchor(mother, n, fragments[f].offset.data());
    if (fix_true_density_) fix_true_density_->vector_atom[n] = rho_true;
    double *data = fix_data_->array_atom[n];
    try {
      // N is the mother's, copied by inherit_state() above
      data[STRENGTH] = settings_.size_scaled(strength_.draw(atom->tag[n], generation), 2.0 * r, scale_of(n));
    } catch (const crush::ModelError &e) {
      particle_error(atom->tag[n], r, density, "drawing the strength of this fragment", e);
    }
    data[GENERATION] = generation;
    data[RATIO] = 0.0;
  }
  return removed;
}

// Deletes from the highest index down, so that no pending index is moved before it is deleted.
void FixCrush::delete_mothers(std::vector<int> &mothers)
{
  std::sort(mothers.begin(), mothers.end());
  for (std::size_t k = mothers.size(); k-- > 0;) {
    atom->avec->copy(atom->nlocal - 1, mothers[k], 1);
    atom->nlocal--;
  }
}


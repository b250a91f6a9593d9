/* ----------------------------------------------------------------------
   liggghts-crush: fix crush and the grains that another fix drives, holds or anchors
   (see fix_crush_driven_grains.h).
------------------------------------------------------------------------- */
#include "fix_crush_driven_grains.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "atom.h"
#include "compute.h"
#include "error.h"
#include "fix_insert_stream.h"
#include "fix_move.h"
#include "fix_multisphere.h"
#include "fix_property_atom.h"
#include "fix_store.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {

bool style_is(const Fix *fix, const char *style) { return strncmp(fix->style, style, strlen(style)) == 0; }

}  // namespace

void CrushDrivenGrains::find(const char *crush_id, int groupbit)
{
  find_fixes();
  find_origins();
  refuse_first(crush_id, groupbit);
}

void CrushDrivenGrains::find_fixes()
{
  bodies_.clear();
  variable_moves_.clear();
  streams_.clear();
  springs_.clear();
  release_ = NULL;
  for (int k = 0; k < modify->nfix; k++) {
    Fix *fix = modify->fix[k];
    if (dynamic_cast<FixMultisphere *>(fix) || style_is(fix, "rigid")) bodies_.push_back(fix);  // also 'concave'
    else if (strcmp(fix->style, "move") == 0 && !static_cast<FixMove *>(fix)->takes_new_atoms())
      variable_moves_.push_back(fix);
    else if (strcmp(fix->style, "spring/self") == 0) springs_.push_back(fix);
    else if (FixInsertStream *stream = dynamic_cast<FixInsertStream *>(fix)) streams_.push_back(stream);
  }
  // Every insert/stream shares the first one's release data (fix_insert_stream.cpp, post_create).
  if (!streams_.empty()) release_ = streams_.front()->fix_prop_release();
}

void CrushDrivenGrains::find_origins()
{
  origins_.clear();
  for (int k = 0; k < modify->ncompute; k++) {
    const Compute *compute = modify->compute[k];
    if (strcmp(compute->style, "displace/atom") != 0 && strcmp(compute->style, "msd") != 0) continue;
    const int store = modify->find_fix((std::string(compute->id) + "_COMPUTE_STORE").c_str());
    if (store >= 0) origins_.push_back(static_cast<FixStore *>(modify->fix[store]));
  }
}

// Collective: the first grain of the group that a refusing fix holds, by tag on every processor alike.
void CrushDrivenGrains::refuse_first(const char *crush_id, int groupbit) const
{
  int first = INT_MAX;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && refusing_fix(i)) first = std::min(first, static_cast<int>(atom->tag[i]));
  int first_all = INT_MAX;
  MPI_Allreduce(&first, &first_all, 1, MPI_INT, MPI_MIN, world);
  if (first_all == INT_MAX) return;
  if (first == first_all) refuse(crush_id, first_all, refusing_fix(atom->map(first_all)));
  MPI_Barrier(world);  // the owner stops the run
}

bool CrushDrivenGrains::in_group(int i, const Fix *fix) const { return (atom->mask[i] & fix->groupbit) != 0; }

const char *CrushDrivenGrains::refusing_fix(int i) const
{
  for (Fix *fix : bodies_) {
    // a multisphere fix's group holds every particle; its bodies are the ones it lists
    const FixMultisphere *multisphere = dynamic_cast<FixMultisphere *>(fix);
    const bool member = multisphere ? multisphere->belongs_to(i) >= 0 : in_group(i, fix);
    if (member) return fix->style;
  }
  for (Fix *fix : variable_moves_)
    if (in_group(i, fix)) return "move (style variable)";
  return NULL;
}

void CrushDrivenGrains::refuse(const char *crush_id, tagint tag, const char *style) const
{
  char msg[512];
  if (strncmp(style, "move", 4) == 0)
    snprintf(msg, sizeof(msg), "Fix crush (id %s): particle %ld is moved by fix %s, which cannot take new "
             "atoms (LIGGGHTS): leave its group out of fix crush's group, or move it with style linear, "
             "wiggle or rotate", crush_id, static_cast<long>(tag), style);
  else
    snprintf(msg, sizeof(msg), "Fix crush (id %s): particle %ld belongs to a rigid body of fix %s: a body's "
             "spheres cannot break into fragments; leave the bodies out of fix crush's group", crush_id,
             static_cast<long>(tag), style);
  error->one(FLERR, msg);
}

// As insert/stream's end_of_step reads its release data: [3] the insertion step (0: not inserted by
// a stream), [release_step_index()] the release step, until which the grain is carried.
bool CrushDrivenGrains::held(int i) const
{
  if (!release_) return false;
  const double *release = release_->array_atom[i];
  if (std::fabs(release[3]) < 1e-13) return false;
  for (FixInsertStream *stream : streams_)
    if (in_group(i, stream)) {
      const bigint release_step = static_cast<bigint>(release[stream->release_step_index()] + 1e-14);
      return update->ntimestep <= release_step;
    }
  return false;
}

bool CrushDrivenGrains::driving_property(const FixPropertyAtom *fix) const { return fix == release_; }

// Unwrapped positions (m): fix spring/self keeps its anchors private, and its exchange packs them
// as three values; a compute's fix store holds the original positions in astore.
void CrushDrivenGrains::anchor(int mother, int fragment, const double *offset) const
{
  for (FixStore *origin : origins_) {
    if (!in_group(mother, origin)) continue;
    for (int k = 0; k < 3; k++) origin->astore[fragment][k] = origin->astore[mother][k] + offset[k];
  }
  for (Fix *spring : springs_) {
    if (!in_group(mother, spring)) continue;
    double anchor[3];
    spring->pack_exchange(mother, anchor);
    for (int k = 0; k < 3; k++) anchor[k] += offset[k];
    spring->unpack_exchange(fragment, anchor);
  }
}

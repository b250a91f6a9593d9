/* ----------------------------------------------------------------------
   liggghts-crush: fix crush (see fix_crush.h and doc/fix_crush.txt).
------------------------------------------------------------------------- */
#include "fix_crush.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <string>

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "fix_crush_driven_grains.h"
#include "fix_crush_family_check.h"
#include "fix_crush_list_insertion.h"
#include "crush_breakage_limit.h"
#include "crush_check_bound.h"
#include "crush_constants.h"
#include "crush_csv_rows.h"
#include "crush_fragments.h"
#include "crush_model_error.h"
#include "domain.h"
#include "region.h"
#include "error.h"
#include "input_keyword.h"
#include "type_materials.h"
#include "fix_property_atom.h"
#include "force.h"
#include "irregular.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "output.h"
#include "thermo.h"
#include "pair_gran.h"
#include "fix_wall_gran.h"
#include "update.h"
#include "hertz_mindlin_scaled_law.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

enum Output { EVENTS = 0, REMOVED_VOLUME = 1, LARGEST_RATIO = 2, REPLACE_SECONDS = 3, CHECKED_STEPS = 4,
              OUTFLOW_VOLUME = 5, OUTFLOW_PARTICLES = 6, TRUE_MASS = 7, LARGEST_DENSITY_SCALE = 8,
              INSERTED_STEPS = 9, HELD_AT_LIMIT = 10, NOUTPUT = 11 };  // vector

crush::CrushSettings parse(Fix *fix, Error *error, int me, int narg, char **arg)
{
  crush::CrushSettings settings;
  fix_input(fix, error, [&] { settings = crush::parse_crush_settings(std::vector<std::string>(arg + 3, arg + narg)); });
  for (const std::string &w : crush::suspicious_settings(settings)) fix_warning(fix, error, me, w);
  return settings;
}

// Each particle's F_n / F_lim of this step, load / (pi sigma_lim)^3, into data[i][RATIO]; clears
// the load for the next step; returns the largest ratio in the group. (The product would be 0 x inf
// for an unloaded particle of zero strength, hence the test.) A function of its own, so that the
// running maximum stays in a register.
double store_ratios(int n, double *load, const double *strength_term, const int *mask, int groupbit,
                    double **data)
{
  double largest = 0.0;
  for (int i = 0; i < n; i++) {
    const double ratio = crush::force_ratio(load[i], strength_term[i]);
    load[i] = 0.0;
    data[i][FixCrush::RATIO] = ratio;
    const double counted = (mask[i] & groupbit) ? ratio : 0.0;
    largest = counted > largest ? counted : largest;
  }
  return largest;
}

}  // namespace

FixCrush::FixCrush(LAMMPS *lmp, int narg, char **arg) :
  Fix(lmp, narg, arg),
  settings_(parse(this, error, comm->me, narg, arg)),
  strength_(settings_.distribution, settings_.sigma_lim0, settings_.cv, settings_.weibull_m, settings_.seed),
  nfrag_(static_cast<int>(crush::fragment_layout(settings_.layout, 1.0).size())),
  region_(NULL), fix_data_(NULL), driven_(NULL), family_check_(NULL), data_id_(NULL), fix_true_density_(NULL), true_density_id_(NULL), fix_scale_(NULL), limit_factor_(NULL), irregular_(NULL), list_insertion_(NULL), inserting_(false), inserted_steps_(0), held_at_limit_(0), log_(NULL),
  events_total_(0), removed_volume_(0.0), outflow_volume_(0.0), outflow_particles_(0), outflow_reported_(false),
  max_ratio_(0.0), local_max_ratio_(0.0), max_ratio_step_(-1),
  smallest_fragment_size_(0.0), initial_largest_size_(0.0), next_tag_(1), replace_seconds_(0.0),
  particle_count_(0), initialized_(false), refresh_needed_(true), recording_(true), box_reference_{0.0, 0.0, 0.0},
  allowed_displacement_(0.0), force_check_(true), check_now_(true), checked_steps_(0), restart_step_(-1),
  log_opened_(false), multi_advised_(false), lists_advised_(false), redraw_pending_(settings_.redraw)
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->density_flag)
    error->all(FLERR, "fix crush needs 'atom_style granular' (radius, mass and density per atom)");
  if (atom->map_style == 0)
    error->all(FLERR, "fix crush needs an atom map: add 'atom_modify map array' before the box is created");
  for (int k = 0; k < modify->nfix; k++)
    if (strcmp(modify->fix[k]->style, "crush") == 0)
      error->all(FLERR, "fix crush: only one fix crush may be defined");

  vector_flag = 1;
  size_vector = NOUTPUT;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 3;
  peratom_freq = 1;
  restart_global = 1;
  force_reneighbor = 1;
  next_reneighbor = -1;

  irregular_ = new Irregular(lmp);
  list_insertion_ = new CrushListInsertion(lmp);
  driven_ = new CrushDrivenGrains(lmp);
  family_check_ = new CrushFamilyCheck(lmp);
  memory->create(limit_factor_, atom->ntypes + 1, atom->ntypes + 1, "crush:limit_factor");
  recorder_.limit_factor = limit_factor_;
  recorder_.total_force = settings_.total_force;
  ContactLoadMonitor::attach(lmp, &recorder_);

}

// At the first init, once restart() has said whether this run continues one: a continued run keeps
// the rows of the steps before the restart's (the killed run may have logged later ones; the events
// pending at the restart are logged again when replaced), a new run starts the file.
void FixCrush::open_log()
{
  log_opened_ = true;
  if (comm->me != 0 || settings_.log_file.empty()) return;
  std::string kept;
  bool continued = false;
  if (restart_step_ >= 0) {
    std::string text;
    if (crush::read_text_file(settings_.log_file, text)) {
      int dropped = 0;
      kept = crush::trim_rows(text, restart_step_, true, dropped);
      continued = kept.find('\n') != std::string::npos;
      if (continued && screen)
        fprintf(screen, "fix crush: continuing the event log %s from step " BIGINT_FORMAT " (%d rows of later steps dropped)\n",
                settings_.log_file.c_str(), restart_step_, dropped);
    }
  }
  log_ = fopen(settings_.log_file.c_str(), "w");
  if (!log_) {
    const std::string msg = "fix crush: cannot open the event log '" + settings_.log_file + "' (keyword 'log')";
    error->one(FLERR, msg.c_str());
  }
  if (continued) {
    fputs(kept.c_str(), log_);
  } else {
    fprintf(log_, "step,tag,diameter,generation,force_ratio,x,y,z");
    for (int f = 1; f <= nfrag_; f++) fprintf(log_, ",fragment_%d", f);
    fprintf(log_, "\n");
  }
  fflush(log_);
}

FixCrush::~FixCrush()
{
  ContactLoadMonitor::attach(lmp, NULL);
  if (log_) fclose(log_);
  delete irregular_;
  delete list_insertion_;
  delete driven_;
  delete family_check_;
  if (neighbor->insertion_handler == this) neighbor->insertion_handler = NULL;
  memory->destroy(limit_factor_);
  if (data_id_ && modify->find_fix(data_id_) >= 0) modify->delete_fix(data_id_);
  delete[] data_id_;
  if (true_density_id_ && modify->find_fix(true_density_id_) >= 0) modify->delete_fix(true_density_id_);
  delete[] true_density_id_;
}

// Per-atom data in a restartable fix property/atom: sigma_lim (-1 = not drawn yet), generation, ratio.
void FixCrush::post_create()
{
  const std::string name = std::string("crush_data_") + id;
  data_id_ = new char[name.size() + 1];
  strcpy(data_id_, name.c_str());
  const char *fixarg[11] = {data_id_, "all", "property/atom", data_id_, "vector", "yes", "no", "no",
                            "-1.", "0.", "0."};
  modify->add_fix(11, const_cast<char **>(fixarg));
  fix_data_ = static_cast<FixPropertyAtom *>(
      modify->find_fix_property(data_id_, "property/atom", "vector", 3, 0, style));
  create_true_density();
}

int FixCrush::setmask()
{
  return PRE_FORCE | END_OF_STEP | PRE_EXCHANGE;
}

void FixCrush::init()
{
  if (force->newton_pair)
    error->all(FLERR, "fix crush needs 'newton off': each particle must see all of its contacts");
  check_contact_models();
  check_materials();
  check_particles();
  driven_->find(id, groupbit);  // before find_inherited_state(): it names the driving properties
  find_true_density();
  find_scale();
  check_scales();  // before the time-step check below reads the smallest N; again at each reneighboring
  find_inherited_state();
  outflow_reported_ = false;
  setup_limit_factors();
  if (!log_opened_) open_log();
  if (settings_.adaptive) find_moving_walls();
  initialized_ = true;
  fix_data_ = static_cast<FixPropertyAtom *>(
      modify->find_fix_property(data_id_, "property/atom", "vector", 3, 0, style));
  if (settings_.dmin > 0.0) check_time_step(smallest_possible_radius());
  advise_neighbor_multi();
  region_ = NULL;
  if (!settings_.region_id.empty()) {
    const int iregion = domain->find_region(settings_.region_id.c_str());
    if (iregion < 0)
      error->fix_error(FLERR, this, ("keyword 'region': no region '" + settings_.region_id + "'").c_str());
    region_ = domain->regions[iregion];
  }
}

// Only grains inside the region may break (keyword region): a scene crushes where it needs to.
bool FixCrush::may_break(int i) const
{
  if (!breakable(i)) return false;
  const double *x = atom->x[i];
  return !region_ || region_->match(x[0], x[1], x[2]);
}

// Group members at or above the comminution limit: the grains that may break somewhere.
bool FixCrush::breakable(int i) const
{
  if (!(atom->mask[i] & groupbit)) return false;
  const double d = 2.0 * atom->radius[i];
  // dmin is at the deck's N: a particle of its own N_i compares its sand size d / N_i with dmin / N
  return fix_scale_ ? d * settings_.scale_factor >= settings_.dmin * scale_of(i) : d >= settings_.dmin;
}

// Before the run's first exchange: a particle of the group without a positive, finite size or density
// has no strength (eq. 10) and no fragments. A particle beyond a fixed boundary is dropped by that
// exchange: with 'thermo_modify lost error' the run stops here, naming it; otherwise it leaves the
// books as outflow (setup_pre_exchange). A shrink-wrapped box grows to hold it. The run stops naming
// the first.
void FixCrush::check_particles() const
{
  const bool lost_error = output->thermo->lost_policy() == Thermo::LOST_ERROR;
  auto outside = [this, lost_error](const double *x) { return lost_error && leaves_box(x); };
  const int first_all = first_failing([this, &outside](int i) {
    const double r = atom->radius[i], rho = atom->density[i];
    const bool bad_data = (atom->mask[i] & groupbit) && !(r > 0.0 && std::isfinite(r) && rho > 0.0 && std::isfinite(rho));
    return bad_data || outside(atom->x[i]);
  });
  if (!first_all) return;
  const int i = atom->map(first_all);
  if (i >= 0 && i < atom->nlocal) {
    char msg[512];
    const double *x = atom->x[i];
    if (outside(x))
      snprintf(msg, sizeof(msg), "Fix crush (id %s): particle %d lies beyond a fixed boundary of the box, at "
               "(%g %g %g), and 'thermo_modify lost error' forbids losing it: keep the particles inside the box",
               id, first_all, x[0], x[1], x[2]);
    else
      snprintf(msg, sizeof(msg), "Fix crush (id %s): particle %d has radius %g m and density %g kg/m^3: both must "
               "be finite and > 0 (set ... diameter, density; create_atoms; read_data)", id, first_all,
               atom->radius[i], atom->density[i]);
    error->one(FLERR, msg);
  }
  MPI_Barrier(world);  // the owner stops the run
}

// The smallest tag over all processors of a local particle for which fails(i), 0 where none: the
// particle a check names, on every processor alike.
int FixCrush::first_failing(const std::function<bool(int)> &fails) const
{
  int first = std::numeric_limits<int>::max();
  for (int i = 0; i < atom->nlocal; i++)
    if (fails(i)) first = std::min(first, static_cast<int>(atom->tag[i]));
  int first_all = 0;
  MPI_Allreduce(&first, &first_all, 1, MPI_INT, MPI_MIN, world);
  return first_all == std::numeric_limits<int>::max() ? 0 : first_all;
}

// Every granular contact, pair or wall, feeds the check through LIGGGHTS' granular pair loop and wall
// (patches/0009), whatever its models: the pair style must be granular, and the normal models must
// have what the chosen force and 'every adaptive' read.
void FixCrush::check_contact_models()
{
  PairGran *pair = static_cast<PairGran *>(force->pair_match("gran", 0));
  if (!pair)
    error->fix_error(FLERR, this, "needs a granular pair style ('pair_style gran model ...'): its contacts "
                                  "supply the normal forces of the breakage check");
  check_normal_model("pair_style gran", [pair](const char *m) { return pair->contact_match("normal", m); });
  for (int k = 0; k < modify->nfix; k++)
    if (strcmp(modify->fix[k]->style, "wall/gran") == 0) {
      FixWallGran *wall = static_cast<FixWallGran *>(modify->fix[k]);
      check_normal_model("fix " + std::string(wall->id) + " wall/gran",
                         [wall](const char *m) { return wall->contact_match("normal", m); });
    }
}

// One pair style or wall: is(name) says whether its normal model is that one.
void FixCrush::check_normal_model(const std::string &who, const std::function<bool(const char *)> &is)
{
  // k_n U is the elastic force of these (the secant stiffness); the others are elasto-plastic or
  // keep no stiffness, and only their total F_n means something.
  static const char *const elastic[] = {"hertz/scaled", "hertz", "hertz/stiffness", "hooke", "hooke/stiffness"};
  static const char *const others[] = {"hooke/hysteresis", "luding", "edinburgh", "edinburgh/stiffness", "thornton_ning"};
  std::string model = "a custom one";
  for (const char *m : others)
    if (is(m)) model = m;
  bool has_elastic = false;
  for (const char *m : elastic)
    if (is(m)) has_elastic = true, model = m;
  if (settings_.adaptive && !is("hertz/scaled"))
    error->fix_error(FLERR, this, ("keyword 'every adaptive' bounds the growth of Hertzian contact forces (eq. 8, "
                                   "model hertz/scaled), but " + who + " uses model " + model +
                                   ": use 'every 1' or 'every N'").c_str());
  if (!settings_.total_force && !has_elastic)
    error->fix_error(FLERR, this, ("keyword 'force elastic' (the default) reads k_n U, which is not the elastic "
                                   "force of " + who + "'s model " + model + " (elasto-plastic, or without "
                                   "k_n): add 'force total' (its normal force with damping)").c_str());
}

// E' of eq. 4 needs each type's elastic constants, whatever the contact law: a deck of hooke/stiffness
// may not define them.
void FixCrush::check_materials()
{
  for (const char *name : {"youngsModulus", "poissonsRatio"})
    if (!modify->find_fix_property(name, "property/global", "peratomtype", 0, 0, style, false))
      error->fix_error(FLERR, this, (std::string("the breakage check (eq. 5) needs the grains' Hertzian contact "
                                                 "area, from E and nu of every type: define 'fix ID all "
                                                 "property/global ") + name + " peratomtype ...'").c_str());
}

// (4 E'/3)^2 per type pair, E' of eq. 4 from the types' youngsModulus and poissonsRatio:
// F_lim = (pi sigma_lim)^3 r'^2 / (4 E'/3)^2 (eq. 5).
void FixCrush::setup_limit_factors()
{
  const int ntypes = atom->ntypes;
  ratio_coefficient_.assign(ntypes + 1, 0.0);
  for (int a = 1; a <= ntypes; a++)
    for (int b = 1; b <= ntypes; b++) {
      try {
        limit_factor_[a][b] = crush::limit_factor(crush::effective_modulus(type_material(modify, ntypes, a, style),
                                                                           type_material(modify, ntypes, b, style)));
        const double normal = crush::hertz_mindlin_coefficients(type_shear_material(modify, ntypes, a, style),
                                                                type_shear_material(modify, ntypes, b, style)).normal;
        ratio_coefficient_[a] = std::max(ratio_coefficient_[a], crush::ratio_coefficient(normal, limit_factor_[a][b]));
      } catch (const crush::ModelError &e) {
        const std::string msg = std::string("fix crush: youngsModulus/poissonsRatio: ") + e.what();
        error->all(FLERR, msg.c_str());
      }
    }
}

// All slots, local and ghost, start at zero. Needed only when the atoms were renumbered
// (reneighboring) or a setup force computation recorded into them: on other steps end_of_step()
// zeroes each local slot it has read, and ghost slots are never read.
void FixCrush::refresh_recorder()
{
  load_.assign(atom->nlocal + atom->nghost, 0.0);
  recorder_.load = load_.data();
  array_atom = fix_data_->array_atom;
  refresh_needed_ = false;
}

void FixCrush::draw_missing_strengths()
{
  double **data = fix_data_->array_atom;
  const int *tag = atom->tag;
  const double *radius = atom->radius;
  for (int i = 0; i < atom->nlocal; i++)
    if (data[i][STRENGTH] < 0.0) {
      try {
        data[i][STRENGTH] = settings_.size_scaled(strength_.draw(tag[i], static_cast<int>(data[i][GENERATION])),
                                                  2.0 * radius[i], scale_of(i));
      } catch (const crush::ModelError &e) {
        particle_error(tag[i], radius[i], atom->density[i], "drawing its strength", e);
      }
    }
}

// 'redraw yes', once, at the first setup: the strengths read from a restart file (a chamber consolidated
// with crushing, the uncrushable reference to follow) are drawn anew from this fix's distribution.
void FixCrush::discard_strengths()
{
  double **data = fix_data_->array_atom;
  for (int i = 0; i < atom->nlocal; i++) data[i][STRENGTH] = -1.0;
  redraw_pending_ = false;
}

// A plain-model error about one particle: the run stops naming it (this processor alone may see it).
void FixCrush::particle_error(tagint tag, double radius, double density, const char *doing,
                              const crush::ModelError &e) const
{
  char msg[1024];
  snprintf(msg, sizeof(msg), "Fix crush (id %s): particle %ld (radius %g m, density %g kg/m^3), %s: %s", id,
           static_cast<long>(tag), radius, density, doing, e.what());
  error->one(FLERR, msg);
}

void FixCrush::setup_pre_force(int vflag)
{
  if (redraw_pending_) discard_strengths();
  bigint n = atom->nlocal;
  MPI_Allreduce(&n, &particle_count_, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (initial_largest_size_ == 0.0) {
    double dmax = 0.0;
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & groupbit) dmax = std::max(dmax, 2.0 * atom->radius[i] / scale_of(i));
    MPI_Allreduce(&dmax, &initial_largest_size_, 1, MPI_DOUBLE, MPI_MAX, world);
  }
  family_check_->check(id, true);  // commands between runs may have moved fragments too
  pre_force(vflag);
}

// Atoms appear (fragments, fix insert, ...) and are renumbered only when LIGGGHTS reneighbors:
// the per-atom work of this step is then done once, not every step.
void FixCrush::pre_force(int)
{
  if (!initialized_)
    error->all(FLERR, "fix crush was defined after the last full run setup ('run ... pre no'): run once "
                      "with 'pre yes' (or 'run 0') after defining it");
  family_check_->check(id, false);
  const bool renumbered = refresh_needed_ || neighbor->atoms_added(update->ntimestep);
  if (renumbered) {
    refresh_recorder();
    fill_true_densities();
    check_scales();
    draw_missing_strengths();
    update_strength_terms();
    if (settings_.adaptive) update_ratio_growth();
  }
  check_now_ = decide_check(renumbered);
  record_on_check_steps();
  if (check_now_ && settings_.adaptive) store_check_reference();
}

// With 'every' > 1 the contact models record loads only on the steps that are checked: on the
// others the recorder is detached, and the per-contact cost is that of no fix crush at all.
void FixCrush::record_on_check_steps()
{
  if (check_now_ == recording_) return;
  ContactLoadMonitor::attach(lmp, check_now_ ? &recorder_ : NULL);
  recording_ = check_now_;
}

// 'every N': every N-th step. 'every adaptive': after atoms were renumbered or created (reneighboring),
// at a run's first step, and whenever a body moved far enough since the last check that a grain
// might have reached its limit (crush_check_bound.h): the same steps find the same events as
// 'every 1'.
bool FixCrush::decide_check(bool renumbered)
{
  if (!settings_.adaptive) return update->ntimestep % settings_.every == 0;
  if (renumbered || force_check_) {
    force_check_ = false;
    return true;
  }
  return largest_displacement() >= allowed_displacement_;
}

// 1 / (pi sigma_lim)^3 per local atom, so that each step's check multiplies instead of divides.
// Infinite for a particle of zero strength: it breaks under any load.
void FixCrush::update_strength_terms()
{
  double **data = fix_data_->array_atom;
  strength_term_.resize(atom->nlocal);
  for (int i = 0; i < atom->nlocal; i++) strength_term_[i] = crush::strength_term(data[i][STRENGTH]);
}

// Modify::setup() has just reset the per-atom data of a new fix property/atom to its defaults
// (strength -1): draw again, and clear what the setup force computation recorded.
void FixCrush::setup(int)
{
  draw_missing_strengths();
  refresh_needed_ = true;
  force_check_ = true;
  choose_event_lists();
  if (!found_.empty()) neighbor->request_rebuild();  // events found at the last run's last step
}

// 'event_lists insert': this run's lists exist now (the neighbor's init follows the fixes'). Where
// a list or fix cannot take fragments between builds, every event step rebuilds, said once.
void FixCrush::choose_event_lists()
{
  std::string reason = settings_.insert_lists ? list_insertion_->unsupported_reason() : "event_lists rebuild";
  inserting_ = reason.empty();
  if (inserting_) {
    if (neighbor->insertion_handler && neighbor->insertion_handler != this)
      error->all(FLERR, "fix crush: another fix adds particles to the neighbour lists between builds");
    neighbor->insertion_handler = this;
  } else if (neighbor->insertion_handler == this) {
    neighbor->insertion_handler = NULL;
  }
  if (!inserting_ && settings_.insert_lists && comm->me == 0 && !lists_advised_) {
    const std::string msg = "fix crush: event steps rebuild the neighbour lists (" + reason + ")";
    error->message(FLERR, msg.c_str());
    lists_advised_ = true;
  }
}

void FixCrush::end_of_step()
{
  // Nothing was recorded on the other steps: the ratios stay those of the last check.
  if (!check_now_) return;
  checked_steps_++;
  double **data = fix_data_->array_atom;
  array_atom = data;
  const int *mask = atom->mask;
  const double local_max = store_ratios(atom->nlocal, load_.data(), strength_term_.data(), mask, groupbit, data);
  // The mothers, in a second pass: this step's loop stays free of calls, and is skipped when no
  // particle here reached its limit (nearly every step).
  std::vector<int> mothers;
  if (local_max >= 1.0) {
    if (region_) region_->prematch();  // a moving region: its position at this step
    for (int i = 0; i < atom->nlocal; i++) {
      if (data[i][RATIO] < 1.0 || !may_break(i)) continue;
      // A grain an insertion still carries has no free grain's forces: it waits for its release.
      if (driven_->held(i)) held_at_limit_++;
      else mothers.push_back(i);
    }
  }
  local_max_ratio_ = local_max;
  max_ratio_step_ = -1;  // reduced over processors when output asks for it, not every step
  if (settings_.adaptive) schedule_next_check();
  // No reduction here: a processor whose grains broke asks for the next step's rebuild or
  // insertion, and the request rides on the neighbour list's distance check (request_replacement).
  // The events are agreed where every processor meets: at that rebuild's pre_exchange, or in
  // insert_without_rebuild().
  if (settings_.check_lists && neighbor->last_insertion > neighbor->lastcall) list_insertion_->verify();
  if (mothers.empty()) return;
  record_events(mothers);
  request_replacement(mothers);
}

// Grains away from every boundary are replaced at the next step without a rebuild, if every
// processor's are (Neighbor::decide); any other event asks for the rebuild.
void FixCrush::request_replacement(const std::vector<int> &mothers)
{
  if (inserting_ && list_insertion_->can_take(mothers)) neighbor->request_insertion();
  else neighbor->request_rebuild();
}

// This processor's mothers, as the events all processors will agree on (agree_on_events).
void FixCrush::record_events(const std::vector<int> &mothers)
{
  double **data = fix_data_->array_atom;
  for (int i : mothers)
    found_.push_back({atom->tag[i], static_cast<int>(data[i][GENERATION]), 2.0 * atom->radius[i], data[i][RATIO],
                      {atom->x[i][0], atom->x[i][1], atom->x[i][2]}});
}

// Collective, at every rebuild and insertion (and before a restart is written): one gather tells
// each processor's events and particles, and whether its events can be replaced in place. Crushing
// only adds particles, and the particles that left the box are counted as they leave
// (count_outflow): during a run, fewer than that means particles vanished by other means, and the
// volume books would no longer balance. Then every processor gets every event, sorted by tag: the
// order that numbers the fragments. Returns whether every processor's can be replaced in place.
bool FixCrush::agree_on_events(bool count_particles, bool replaceable_here)
{
  const int nprocs = comm->nprocs, size = static_cast<int>(sizeof(Event));
  const int mine[3] = {static_cast<int>(found_.size()) * size, atom->nlocal, replaceable_here ? 1 : 0};
  std::vector<int> all(3 * nprocs);
  MPI_Allgather(mine, 3, MPI_INT, all.data(), 3, MPI_INT, world);
  std::vector<int> counts(nprocs), displs(nprocs);
  int total = 0;
  bigint particles = 0;
  bool replaceable = true;
  for (int p = 0; p < nprocs; p++) {
    counts[p] = all[3 * p];
    displs[p] = total;
    total += counts[p];
    particles += all[3 * p + 1];
    replaceable = replaceable && all[3 * p + 2] == 1;
  }
  if (count_particles) check_particle_count(particles);
  if (total == 0) return replaceable;
  // Events are plain structs, identical in layout on every processor: gathered as bytes.
  std::vector<Event> events(total / size);
  MPI_Allgatherv(found_.data(), mine[0], MPI_BYTE, events.data(), counts.data(), displs.data(), MPI_BYTE, world);
  found_.clear();
  pending_.insert(pending_.end(), events.begin(), events.end());
  std::sort(pending_.begin(), pending_.end(), [](const Event &a, const Event &b) { return a.tag < b.tag; });
  return replaceable;
}

void FixCrush::check_particle_count(bigint particles)
{
  if (particles < particle_count_) {
    char msg[400];
    snprintf(msg, sizeof(msg), "fix crush: " BIGINT_FORMAT " particles vanished during the run without leaving the box "
             "(a fix or command deleted them): the volume books no longer balance; fix crush counts only the "
             "particles that leave through a fixed boundary ('thermo_modify lost')", particle_count_ - particles);
    error->all(FLERR, msg);
  }
  particle_count_ = particles;
}

// Neighbor::decide() at the step after the events, when every processor asked for an insertion:
// the mothers' spheres must lie inside their sub-domains (no fragment to migrate). Otherwise the
// agreed events wait for the rebuild this returns false for (pre_exchange).
bool FixCrush::insert_without_rebuild()
{
  if (!agree_on_events(true, list_insertion_->inside_subdomain(found_here()))) return false;
  if (!pending_.empty()) {
    replace_pending(true);
    inserted_steps_++;
  }
  if (settings_.check_lists) list_insertion_->verify();
  return true;
}

// The agreed events replaced (timed for f_ID[4]), then forgotten.
void FixCrush::replace_pending(bool in_place)
{
  const double start = MPI_Wtime();
  replace_mothers(in_place);
  replace_seconds_ += MPI_Wtime() - start;
  pending_.clear();
}

// The local indices of this processor's events not yet agreed.
std::vector<int> FixCrush::found_here() const
{
  std::vector<int> mothers;
  for (const Event &e : found_) mothers.push_back(atom->map(e.tag));
  return mothers;
}

// The agreed events are replaced before the exchange moves their fragments (fix_crush_replacement.cpp);
// then the particles that the exchange will drop beyond a fixed boundary leave the books
// (fix_crush_outflow.cpp).
void FixCrush::pre_exchange()
{
  agree_on_events(true);
  if (!pending_.empty()) {
    replace_pending(false);
    next_reneighbor = -1;
  }
  count_outflow();
}

// The run's setup exchanges atoms too: particles beyond a fixed boundary at a run's start leave there.
void FixCrush::setup_pre_exchange()
{
  count_outflow();
}

void FixCrush::log_events(const std::vector<Event> &events, tagint first_new_tag)
{
  if (!log_) return;
  for (std::size_t k = 0; k < events.size(); k++) {
    const Event &e = events[k];
    fprintf(log_, BIGINT_FORMAT "," BIGINT_FORMAT ",%.10g,%d,%.10g,%.10g,%.10g,%.10g", update->ntimestep - 1,
            static_cast<bigint>(e.tag), e.diameter, e.generation, e.ratio, e.x[0], e.x[1], e.x[2]);
    for (int f = 0; f < nfrag_; f++)
      fprintf(log_, "," BIGINT_FORMAT, static_cast<bigint>(first_new_tag + nfrag_ * static_cast<tagint>(k) + f));
    fprintf(log_, "\n");
  }
  fflush(log_);
}

// The smallest particle that can exist: the smallest fragment of a grain just at dmin (for the
// smallest N present: dmin N_i / N), or a smaller particle already present.
double FixCrush::smallest_possible_radius() const
{
  const double dmin = fix_scale_ ? settings_.dmin * smallest_scale() / settings_.scale_factor : settings_.dmin;
  return std::min(smallest_radius(), crush::smallest_fragment_ratio(settings_.layout) * 0.5 * dmin);
}

// The smallest particle radius on all processors (1e300 without particles).
double FixCrush::smallest_radius() const
{
  double rmin = 1e300, rmin_all = 0.0;
  for (int i = 0; i < atom->nlocal; i++) rmin = std::min(rmin, atom->radius[i]);
  MPI_Allreduce(&rmin, &rmin_all, 1, MPI_DOUBLE, MPI_MIN, world);
  return rmin_all;
}

// Style bin searches about every sphere as far as the largest sphere reaches. Once fragments are a
// quarter of the largest grain or less, style multi (doc/neighbor_multi.txt) finds the same pairs
// searching each size class only as far as it reaches: said once, with what it saved in a user's deck.
void FixCrush::advise_neighbor_multi()
{
  if (multi_advised_ || neighbor->style != 1) return;  // 1: bin
  double r_max = 0.0, r_max_all = 0.0;
  for (int i = 0; i < atom->nlocal; i++) r_max = std::max(r_max, atom->radius[i]);
  MPI_Allreduce(&r_max, &r_max_all, 1, MPI_DOUBLE, MPI_MAX, world);
  // without a comminution limit fragments shrink without end: one generation bounds the spread below
  const double r_min = settings_.dmin > 0.0 ? smallest_possible_radius()
                                            : crush::smallest_fragment_ratio(settings_.layout) * smallest_radius();
  if (!(r_min > 0.0 && r_max_all > 4.0 * r_min)) return;
  multi_advised_ = true;
  if (comm->me != 0) return;
  char msg[640];
  snprintf(msg, sizeof(msg), "Fix crush (id %s): the radii will spread from %g m to %g m (%.0f:1%s) as grains "
           "break, and 'neighbor ... bin' searches about every sphere as far as the largest reaches: 'neighbor "
           "SKIN multi' finds the same pairs by size class (doc/neighbor_multi.txt; LIGGGHTS' conveyor "
           "tutorial with crushing took 0.49 of bin's time)\n", id, r_max_all, r_min, r_max_all / r_min,
           settings_.dmin > 0.0 ? "" : " or more: no comminution limit");
  if (screen) fputs(msg, screen);
  if (logfile) fputs(msg, logfile);
}

void FixCrush::check_time_step(double smallest_radius) const
{
  if (!(smallest_radius < 1e300)) return;
  // fix dt/stiffness follows the contacts' own stiffness, which the Rayleigh bound overestimates.
  if (modify->find_fix_style("dt/stiffness", 0)) return;
  // The stiffest, lightest material present sets the Rayleigh time. Scaled fragments keep their
  // grain's r sqrt(rho), on which alone it depends: the particles present bound every fragment to
  // come (radius r sqrt(rho), density 1).
  const bool scaled = settings_.fragment_density == crush::FragmentDensity::scaled;
  double density_all = 1.0;
  if (scaled) {
    smallest_radius = smallest_rayleigh_product();
  } else {
    double density_min = 1e300;
    for (int i = 0; i < atom->nlocal; i++) density_min = std::min(density_min, atom->density[i]);
    MPI_Allreduce(&density_min, &density_all, 1, MPI_DOUBLE, MPI_MIN, world);
  }
  if (!(smallest_radius < 1e300 && density_all < 1e300)) return;
  double dt_limit = 1e300;
  // Only the types of particles present count (wall types are not particles).
  std::vector<int> present(atom->ntypes + 1, 0), present_all(atom->ntypes + 1, 0);
  for (int i = 0; i < atom->nlocal; i++) present[atom->type[i]] = 1;
  MPI_Allreduce(present.data(), present_all.data(), atom->ntypes + 1, MPI_INT, MPI_MAX, world);
  for (int t = 1; t <= atom->ntypes; t++) {
    if (!present_all[t]) continue;
    const crush::ShearMaterial m = type_shear_material(modify, atom->ntypes, t, style);
    try {
      dt_limit = std::min(dt_limit, settings_.rayleigh_fraction *
                                        crush::rayleigh_time_step(smallest_radius, density_all, m));
    } catch (const crush::ModelError &e) {
      error->all(FLERR, (std::string("fix crush: the Rayleigh time-step check: ") + e.what() +
                         " (the smallest radius and density of the particles present)").c_str());
    }
  }
  if (update->dt > dt_limit) {
    char which[160];
    if (scaled)
      snprintf(which, sizeof(which), "r sqrt(rho) %g m sqrt(kg/m^3), the smallest present, which 'fragment_density "
               "scaled' fragments keep", smallest_radius);
    else
      snprintf(which, sizeof(which), "radius %g m, %s", smallest_radius,
               settings_.dmin > 0.0 ? "a fragment of a grain at dmin" : "present after crushing");
    char msg[512];
    snprintf(msg, sizeof(msg),
             "fix crush: time step %g s exceeds %g s, %g of the Rayleigh time of the smallest particle "
             "that can exist (%s): reduce the timestep, raise 'dmin', or change 'rayleigh_fraction'",
             update->dt, dt_limit, settings_.rayleigh_fraction, which);
    error->all(FLERR, msg);
  }
}

double FixCrush::compute_vector(int n)
{
  if (n == EVENTS) return static_cast<double>(events_total_);
  if (n == REMOVED_VOLUME) return removed_volume_;
  if (n == LARGEST_RATIO) {
    // Called by every processor (thermo, variables, fix ave/time), as LAMMPS requires.
    if (max_ratio_step_ != update->ntimestep) {
      MPI_Allreduce(&local_max_ratio_, &max_ratio_, 1, MPI_DOUBLE, MPI_MAX, world);
      max_ratio_step_ = update->ntimestep;
    }
    return max_ratio_;
  }
  if (n == CHECKED_STEPS) return static_cast<double>(checked_steps_);
  if (n == OUTFLOW_VOLUME) return outflow_volume_;
  if (n == OUTFLOW_PARTICLES) return static_cast<double>(outflow_particles_);
  if (n == TRUE_MASS) return true_mass();
  if (n == LARGEST_DENSITY_SCALE) return largest_density_scale();
  if (n == INSERTED_STEPS) return static_cast<double>(inserted_steps_);
  if (n == HELD_AT_LIMIT) {
    bigint held_all = 0;
    MPI_Allreduce(&held_at_limit_, &held_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    return static_cast<double>(held_all);
  }
  return replace_seconds_;
}

// The global state, then the pending events (a restart written at the end of a step in which grains
// broke continues with their replacement, as the uninterrupted run does), as bytes.
namespace {
// The section starts with a name and a version: a file of another layout is refused by name.
const char kRestartName[8] = "crush";
const int kRestartVersion = 4;  // 3: with the outflow; 4: the sizes downscaled (d / N)
const int kRestartVersionModelSizes = 3;  // read too: its two sizes are model diameters at the deck's N
struct RestartHead {
  char name[8];
  int version;
};
struct RestartState {
  bigint events_total, npending, checked_steps;
  double removed_volume, smallest_fragment_size, initial_largest_size;
  tagint next_tag;
  std::uint64_t seed;
};
struct RestartOutflow {  // version 3
  double volume;
  bigint particles;
};
}  // namespace

void FixCrush::write_restart(FILE *fp)
{
  // Every processor writes a restart: the events found at this step travel in it. Between runs a
  // command may have deleted particles: the next run's setup counts them again.
  agree_on_events(false);
  const RestartState state = {events_total_, static_cast<bigint>(pending_.size()), checked_steps_, removed_volume_,
                              smallest_fragment_size_, initial_largest_size_, next_tag_, settings_.seed};
  RestartHead head = {{0}, kRestartVersion};
  std::memcpy(head.name, kRestartName, sizeof(kRestartName));
  if (comm->me == 0) {
    const RestartOutflow outflow = {outflow_volume_, outflow_particles_};
    int size = static_cast<int>(sizeof(RestartHead) + sizeof(RestartState) + sizeof(RestartOutflow) +
                                pending_.size() * sizeof(Event));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(&head, sizeof(RestartHead), 1, fp);
    fwrite(&state, sizeof(RestartState), 1, fp);
    fwrite(&outflow, sizeof(RestartOutflow), 1, fp);
    fwrite(pending_.data(), sizeof(Event), pending_.size(), fp);
  }
}

void FixCrush::restart(char *buf)
{
  RestartHead head;
  std::memcpy(&head, buf, sizeof(RestartHead));
  if (std::memcmp(head.name, kRestartName, sizeof(kRestartName)) != 0) {
    error->fix_error(FLERR, this, "the restart file's fix crush section has no version: it was written by an "
                                  "older liggghts-crush, or is not a fix crush section");
  } else if (head.version != kRestartVersion && head.version != kRestartVersionModelSizes) {
    char msg[256];
    snprintf(msg, sizeof(msg), "the restart file's fix crush section is version %d; this build reads versions %d "
             "and %d", head.version, kRestartVersionModelSizes, kRestartVersion);
    error->fix_error(FLERR, this, msg);
  }
  buf += sizeof(RestartHead);
  restart_step_ = update->ntimestep;
  RestartState state;
  std::memcpy(&state, buf, sizeof(RestartState));
  events_total_ = state.events_total;
  checked_steps_ = state.checked_steps;
  removed_volume_ = state.removed_volume;
  const double downscale = head.version == kRestartVersionModelSizes ? settings_.scale_factor : 1.0;
  smallest_fragment_size_ = state.smallest_fragment_size / downscale;
  initial_largest_size_ = state.initial_largest_size / downscale;
  next_tag_ = state.next_tag;
  if (state.seed != settings_.seed && comm->me == 0)
    error->warning(FLERR, "fix crush: the restart file was written with another 'seed'");
  buf += sizeof(RestartState);
  RestartOutflow outflow;
  std::memcpy(&outflow, buf, sizeof(RestartOutflow));
  outflow_volume_ = outflow.volume;
  outflow_particles_ = outflow.particles;
  buf += sizeof(RestartOutflow);
  pending_.resize(static_cast<std::size_t>(state.npending));
  std::memcpy(pending_.data(), buf, pending_.size() * sizeof(Event));
  if (!pending_.empty()) next_reneighbor = update->ntimestep + 1;
}

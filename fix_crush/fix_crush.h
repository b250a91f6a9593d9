/* ----------------------------------------------------------------------
   liggghts-crush: fix crush, grain crushing by replacement with inscribed fragments
   (Ciantia et al. 2014). See doc/fix_crush.txt.

   Per checked step: the hertz/scaled contact model records each particle's largest F_n / F_lim
   through the ContactLoadRecorder during the pair and wall force computations (pre_force() clears the
   record after reneighboring, end_of_step() as it reads it); end_of_step() finds the particles that
   reached their limit, agrees on them across processors (sorted by tag, so fragment tags and
   strengths never depend on the decomposition), logs them, and schedules a reneighboring;
   pre_exchange() of the next step replaces each by its fragments (fix_crush_replacement.cpp: the
   fragments, what they inherit from their mother, the books; the grains that other fixes drive,
   fix_crush_driven_grains.h), or, for grains away from every
   boundary, insert_without_rebuild() replaces them in place without one
   (fix_crush_list_insertion.h), and counts the grains that leave a
   fixed box (fix_crush_outflow.cpp: 'thermo_modify lost'). With 'scale_atom' each particle carries
   its own upscaling factor N (fix_crush_scale.cpp): eq. 10, the comminution limit and the grading
   read it per particle.
   The physics (limit, strengths, layout, grading) is in the plain crush_*.h files.
------------------------------------------------------------------------- */
#ifdef FIX_CLASS

FixStyle(crush,FixCrush)

#else

#ifndef LMP_FIX_CRUSH_H
#define LMP_FIX_CRUSH_H

#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "crush_model_error.h"
#include "crush_settings.h"
#include "crush_strength.h"
#include "fix.h"
#include "lmptype.h"
#include "contact_load_monitor.h"
#include "neighbor.h"

namespace LAMMPS_NS {

class FixCrush : public Fix, public NeighborInsertion {
 public:
  FixCrush(class LAMMPS *, int, char **);
  ~FixCrush();
  void post_create();
  int setmask();
  void init();
  void setup_pre_force(int);
  void setup(int);
  void pre_force(int);
  void end_of_step();
  void setup_pre_exchange();
  void pre_exchange();
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);
  // 'event_lists insert': the events replaced without a rebuild (fix_crush_list_insertion.h), collective
  bool insert_without_rebuild();

  enum Column { STRENGTH = 0, GENERATION = 1, RATIO = 2 };  // per-atom array (f_crush[i][1..3])

  // For compute crush/gsd.
  const crush::CrushSettings &settings() const { return settings_; }
  double removed_volume() const { return removed_volume_; }
  double outflow_volume() const { return outflow_volume_; }
  // Downscaled sizes (d / N, m): the sand's, whatever N each particle has.
  double smallest_fragment_size() const { return smallest_fragment_size_; }
  double initial_largest_size() const { return initial_largest_size_; }
  // N of local particle i: its own (scale_atom) or the deck's (scale).
  double scale_of(int i) const;

 private:
  // One breakage: the mother's data as agreed by all processors.
  struct Event {
    tagint tag;
    int generation;
    double diameter, ratio, x[3];
  };

  void check_contact_models();
  void check_normal_model(const std::string &who, const std::function<bool(const char *)> &is);
  void check_materials();
  void setup_limit_factors();
  void refresh_recorder();
  void record_on_check_steps();
  bool decide_check(bool renumbered);
  void find_moving_walls();
  class Fix *wall(std::size_t k) const;
  class AbstractMesh *mesh(std::size_t k) const;
  std::vector<double> mesh_nodes(std::size_t k) const;
  double largest_mesh_displacement() const;
  void update_ratio_growth();
  void store_check_reference();
  double largest_displacement() const;
  void schedule_next_check();
  void draw_missing_strengths();
  void discard_strengths();
  void update_strength_terms();
  void check_time_step(double smallest_radius) const;
  void advise_neighbor_multi();
  double smallest_possible_radius() const;
  double smallest_radius() const;
  void record_events(const std::vector<int> &mothers);
  bool agree_on_events(bool count_particles, bool replaceable_here = true);
  void choose_event_lists();
  void request_replacement(const std::vector<int> &mothers);
  std::vector<int> found_here() const;
  void check_particle_count(bigint particles);
  void log_events(const std::vector<Event> &events, tagint first_new_tag);
  void open_log();
  void check_particles() const;
  int first_failing(const std::function<bool(int)> &fails) const;
  // grains that leave the box (fix_crush_outflow.cpp)
  bool leaves_box(const double *x) const;
  void count_outflow();
  void report_outflow(bigint count, double volume);
  void particle_error(tagint tag, double radius, double density, const char *doing,
                      const crush::ModelError &e) const;
  void replace_pending(bool in_place);
  void replace_mothers(bool in_place);
  double replace_one(const std::pair<std::size_t, int> &event, tagint first, double &smallest);
  void replace_in_place(const std::vector<std::pair<std::size_t, int>> &owned, tagint first, double &removed,
                        double &smallest);
  std::vector<std::pair<std::size_t, int>> owned_mothers() const;
  void check_books(double added, double replaced) const;
  void remember_families(tagint first) const;
  void check_unique_tags() const;
  tagint largest_tag() const;
  bool may_break(int i) const;
  bool breakable(int i) const;
  double create_fragments(int mother, tagint first_tag, int generation);
  void delete_mothers(std::vector<int> &mothers);
  // what a fragment inherits (fix_crush_replacement.cpp)
  enum class Inheritance { COPY, SHARE, NEW };
  struct InheritedState {
    class FixPropertyAtom *fix;
    Inheritance rule;
  };
  void find_inherited_state();
  void inherit_state(int mother, int fragment, double mass_share) const;
  // fragment_density scaled: every particle's true density (fix_crush_density.cpp)
  void create_true_density();
  void find_true_density();
  void fill_true_densities();
  double true_density(int i) const;
  double true_mass() const;
  double largest_density_scale() const;
  double smallest_rayleigh_product() const;
  // 'scale_atom': each particle's own N (fix_crush_scale.cpp)
  void find_scale();
  void check_scales() const;
  double smallest_scale() const;

  crush::CrushSettings settings_;
  crush::StrengthDraw strength_;
  const int nfrag_;                  // fragments per event (layout)
  class Region *region_;             // keyword region (NULL: everywhere)
  class FixPropertyAtom *fix_data_;  // per atom: sigma_lim (Pa), generation, last F_n/F_lim
  std::vector<InheritedState> inherited_;  // every other fix property/atom, with its rule
  std::vector<class Fix *> copied_arrays_;  // per-atom arrays without defaults for a new atom: copied
  class CrushDrivenGrains *driven_;        // grains other fixes drive, hold or anchor
  class CrushFamilyCheck *family_check_;   // each event's fragments apart when they first interact
  char *data_id_;
  class FixPropertyAtom *fix_true_density_;  // fragment_density scaled: per atom, its true density
  char *true_density_id_;
  class FixPropertyAtom *fix_scale_;  // 'scale_atom': the user's per-atom N (NULL: the deck's N)
  ContactLoadRecorder recorder_;
  double **limit_factor_;        // per type pair: (4 E'/3)^2
  std::vector<double> load_;         // per local and ghost atom: largest F_n (4 E'/3)^2 / r'^2 this step
  std::vector<double> strength_term_;  // per local atom: 1 / (pi sigma_lim)^3 (Pa^-3), at reneighboring
  // 'every adaptive' (crush_check_bound.h)
  std::vector<double> ratio_coefficient_;  // per type: the largest K over the types it may touch
  std::vector<double> ratio_growth_;       // per local atom: growth_i (0: never breaks), at reneighboring
  std::vector<double> reference_x_;        // per local atom: its position at the last check
  std::vector<double> wall_reference_;     // the fix wall/servo walls' positions at the last check
  std::vector<std::string> wall_ids_;      // the fix wall/servo instances, found by ID at each use
  std::vector<std::string> mesh_ids_;      // the fix mesh/surface instances, likewise
  std::vector<std::vector<double>> mesh_reference_;  // their nodes by element ID at the last check
  double box_reference_[3];
  double allowed_displacement_;            // D below which no grain can reach its limit
  bool force_check_;                       // check the next step (run start)
  bool check_now_;                         // this step is checked
  bigint checked_steps_;
  class Irregular *irregular_;
  class CrushListInsertion *list_insertion_;  // 'event_lists insert': fragments into the lists in place
  bool inserting_;                   // this run's lists and fixes take fragments without a rebuild
  bigint inserted_steps_;            // event steps replaced without a rebuild (f_ID[10])
  bigint held_at_limit_;             // this processor's checks of a held grain at its limit (f_ID[11])
  FILE *log_;

  std::vector<Event> found_;         // this processor's, found at end_of_step, agreed at the next rebuild
  std::vector<Event> pending_;       // agreed by all processors, replaced at that rebuild's pre_exchange
  bigint events_total_;
  double removed_volume_;
  double outflow_volume_;            // the volume of the particles that left the box (m^3)
  bigint outflow_particles_;
  bool outflow_reported_;            // this run has said that particles leave
  double max_ratio_;                 // over all processors, at step max_ratio_step_
  double local_max_ratio_;           // this processor's, at the last end_of_step
  bigint max_ratio_step_;
  double smallest_fragment_size_;    // the smallest fragment made so far, d / N (m): the fines' largest size
  double initial_largest_size_;      // the largest particle at the first setup, d / N (m): I_G's d_max
  tagint next_tag_;                  // the first tag never given out
  double replace_seconds_;           // wall time spent in replace_mothers(), for the event cost
  bigint particle_count_;            // particles at the last rebuild: losses stop the run
  bool initialized_;                 // init() ran: 'run pre no' right after the fix skips it
  bool refresh_needed_;              // clear every load slot at the next pre_force (see refresh_recorder)
  bool recording_;                   // the recorder is attached (with 'every' > 1: on check steps only)
  bigint restart_step_;              // the step of the restart file this run continues (-1: none)
  bool log_opened_;                  // open_log() ran (at the first init)
  bool multi_advised_;               // advise_neighbor_multi() has spoken
  bool lists_advised_;               // choose_event_lists() has said why event steps rebuild
  bool redraw_pending_;              // 'redraw yes': the first setup discards the restart's strengths
};

}  // namespace LAMMPS_NS

#endif
#endif

/* Crushing model (plain C++): the settings of fix crush, parsed and validated from its keywords.

   fix ID group crush sigma_lim0 5e9 cv 1 weibull_m 10 d0 2e-3 seed 1234567 &
       scale 2 dmin 5e-5 every 1 orientation random distribution normal size_effect yes &
       layout fourteen fines_dimension 2.5 rayleigh_fraction 0.3 log crush_events.csv check_tags no &
       region tip force elastic fragment_density true redraw no scale_atom scale_factor &
       event_lists insert check_lists no

   Required: sigma_lim0 (Pa), cv, weibull_m, d0 (m), seed. Every error names the keyword and the
   expected value (ModelError), for the LIGGGHTS adapter to pass to error->all(). */
#ifndef CRUSH_SETTINGS_H
#define CRUSH_SETTINGS_H

#include <cstdint>
#include <string>
#include <vector>

#include "crush_fragment_density.h"
#include "crush_fragments.h"
#include "crush_strength.h"

namespace crush {

struct CrushSettings {
  double sigma_lim0 = 0.0;       // Pa, mean strength at d = N d0 (eq. 10)
  double cv = -1.0;              // coefficient of variation of the strength draw
  double weibull_m = 0.0;        // Weibull modulus: size effect exponent -3/m (eq. 6)
  double d0 = 0.0;               // m, reference diameter
  std::uint64_t seed = 0;        // strength draws and orientations
  double scale_factor = 1.0;     // N, the upscaling factor (sec. 2.4)
  std::string scale_atom;        // a fix property/atom holding each particle's own N ("" = none: N everywhere)
  double dmin = 0.0;             // m, comminution limit: smaller particles never break (0: none)
  int every = 1;                 // check for breakage every this many steps
  bool adaptive = false;         // 'every adaptive': check only when a bound says a grain may break
  bool random_orientation = true;
  StrengthDistribution distribution = StrengthDistribution::normal;
  bool size_effect = true;
  FragmentLayout layout = FragmentLayout::fourteen;
  double fines_dimension = 2.5;  // fractal dimension of the removed volume in the GSD
  double rayleigh_fraction = 0.3;  // largest allowed time step / Rayleigh time of the smallest grain
  std::string log_file;          // CSV event log ("" = none)
  std::string region_id;         // only grains inside this LIGGGHTS region may break ("" = everywhere)
  bool check_tags = false;       // after each replacement, every tag unique over all processors (tests)
  bool total_force = false;      // 'force total': the normal force with damping and cohesion, not k_n U
  FragmentDensity fragment_density = FragmentDensity::true_density;  // 'scaled': the grain's time step
  bool redraw = false;           // 'redraw yes': the strengths a restart file brings are drawn anew
  bool insert_lists = true;      // 'event_lists insert': fragments of interior grains join the lists without a rebuild
  bool check_lists = false;      // after each such insertion, until the next build: every touching pair listed (tests)

  // sigma_lim (Pa) of a particle of diameter d (m) with strength draw s (Pa): eq. 10 or s, with the
  // deck's N or the particle's own scale factor (scale_atom).
  double size_scaled(double s, double d) const;
  double size_scaled(double s, double d, double scale_factor) const;
};

// Parses the keyword/value list that follows 'fix ID group crush'.
CrushSettings parse_crush_settings(const std::vector<std::string> &args);
// Values inside the ranges that are still unlikely to be meant (one message each, for warnings).
std::vector<std::string> suspicious_settings(const CrushSettings &settings);

}  // namespace crush

#endif

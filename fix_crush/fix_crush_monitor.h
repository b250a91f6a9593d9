/* ----------------------------------------------------------------------
   liggghts-crush: the link between the contact models and fix crush.

   A fix crush owns a CrushRecorder; the hertz/scaled normal model asks its CrushMonitor for it at
   each contact and, when one exists, records F_n / F_lim (eq. 5/7/10) for the particle and, if it is
   a local ball, for its partner. Without a fix crush the per-contact cost is one integer compare:
   the monitor re-resolves its recorder only when a crush fix was created or deleted.
------------------------------------------------------------------------- */
#ifndef LMP_FIX_CRUSH_MONITOR_H
#define LMP_FIX_CRUSH_MONITOR_H

#include <cmath>

namespace LAMMPS_NS {

class LAMMPS;

// Records the largest F_n / F_lim per particle over its contacts during one force computation.
// data[i] = {sigma_lim (Pa), generation, largest F_n / F_lim}: fix crush's per-atom array.
class CrushRecorder {
 public:
  CrushRecorder() : data(0), nlocal(0), limit_factor(0) {}

  // F_lim = (pi sigma_lim)^3 (3/(4 E'))^2 r'^2 (eq. 5) with limit_factor[itype][jtype] = (3/(4 E'))^2
  // (1/Pa^2) and r' the contact's effective radius (m); F_n the elastic normal force (N).
  inline void record(int i, int j, bool is_wall, int itype, int jtype, double radi, double radj,
                     double normal_force) const
  {
    const double r_eff = is_wall ? radi : radi * radj / (radi + radj);
    const double base = limit_factor[itype][jtype] * r_eff * r_eff;
    update(data[i], normal_force, base);
    if (!is_wall && j < nlocal) update(data[j], normal_force, base);
  }

  double **data;
  int nlocal;
  double **limit_factor;

 private:
  static inline void update(double *d, double force, double base)
  {
    const double s = 3.14159265358979323846 * d[0];
    const double limit = s * s * s * base;
    // A particle of zero strength breaks under any compressive contact.
    const double r = limit > 0.0 ? force / limit : (force > 0.0 ? HUGE_VAL : 0.0);
    if (r > d[2]) d[2] = r;
  }
};

// Resolves the recorder of the crush fix of one LAMMPS instance, if any.
class CrushMonitor {
 public:
  explicit CrushMonitor(LAMMPS *lmp) : lmp_(lmp), generation_(-1), recorder_(0) {}

  inline const CrushRecorder *recorder()
  {
    if (generation_ != generation) resolve();
    return recorder_;
  }

  // Called by fix crush when it is created (recorder) or deleted (NULL).
  static void attach(LAMMPS *lmp, const CrushRecorder *recorder);

  static int generation;  // changes whenever a recorder is attached or detached

 private:
  void resolve();
  LAMMPS *lmp_;
  int generation_;
  const CrushRecorder *recorder_;
};

}  // namespace LAMMPS_NS

#endif

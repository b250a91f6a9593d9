/* Incremental shear force of the scaled Hertz-Mindlin law (plain C++): PFC's shear update with the
   shear stiffness k_S of eq. 9 (Ciantia et al. 2014), as the tangential model mindlin/scaled uses it.

     F_s <- R(F_s) - k_S v_t dt,      |F_s| <= mu |F_n|   (Coulomb)

   R turns the stored force into the current tangent plane (unit normal e_n) keeping its magnitude:
   the contact plane rotates with the particles. Vectors are 3 doubles; forces in N. */
#ifndef HERTZ_MINDLIN_SHEAR_LAW_H
#define HERTZ_MINDLIN_SHEAR_LAW_H

#include <cmath>

namespace crush {

// R: removes the component of Fs along en and restores the magnitude. A zero force stays zero; a
// force along en (no tangent part left) becomes zero.
inline void rotate_into_tangent_plane(double *Fs, const double *en)
{
  const double before = Fs[0] * Fs[0] + Fs[1] * Fs[1] + Fs[2] * Fs[2];
  if (before == 0.0) return;
  const double dot = Fs[0] * en[0] + Fs[1] * en[1] + Fs[2] * en[2];
  for (int k = 0; k < 3; ++k) Fs[k] -= dot * en[k];
  const double after = Fs[0] * Fs[0] + Fs[1] * Fs[1] + Fs[2] * Fs[2];
  if (after > 0.0) {
    const double s = std::sqrt(before / after);
    for (int k = 0; k < 3; ++k) Fs[k] *= s;
  }
}

// The increment: Fs <- R(Fs) - (k_S dt) v_t, v_t the tangential relative velocity (m/s).
inline void increment_shear_force(double *Fs, const double *en, double kt_dt, const double *vt)
{
  rotate_into_tangent_plane(Fs, en);
  for (int k = 0; k < 3; ++k) Fs[k] -= kt_dt * vt[k];
}

// Coulomb: where |Fs| exceeds the limit mu |F_n| (N), Fs is scaled back onto it (sliding) and true
// is returned; else Fs is left as it is.
// Compared squared: the square root (a long-latency instruction on the contact's critical path) is
// taken only where the contact slides.
inline bool cap_at_coulomb(double *Fs, double limit)
{
  const double magnitude_sq = Fs[0] * Fs[0] + Fs[1] * Fs[1] + Fs[2] * Fs[2];
  if (!(magnitude_sq > limit * limit)) return false;
  const double ratio = limit / std::sqrt(magnitude_sq);  // magnitude_sq > 0 here
  for (int k = 0; k < 3; ++k) Fs[k] *= ratio;
  return true;
}

}  // namespace crush

#endif

/* Crushing model (plain C++): the bound behind fix crush's exact adaptive check ('every adaptive').

   A particle i in a Hertzian contact (eq. 8, F_n = c_N sqrt(2 r') U^(3/2)) of overlap U and effective
   radius r' carries the ratio of eq. 5
     F_n / F_lim = K T_i (U/r')^(3/2),   K = sqrt2 c_N (4E'/3)^2,   T_i = 1 / (pi sigma_lim,i)^3
   so g = (F_n / F_lim)^(2/3) = (K T_i)^(2/3) U/r' grows linearly with the overlap. Between two checks
   a contact's overlap grows by at most the displacements of its two bodies (triangle inequality),
   each at most D, the largest displacement of any particle or wall since the check; and
   r' = r_i r_j/(r_i + r_j) >= r_i r_s/(r_i + r_s), r_s the smallest radius present (a wall: r' = r_i).
   A contact that did not exist at the check started from U <= 0. Hence, for every contact of i,
     g_i(now) <= g_i(check) + 2 D growth_i,   growth_i = (K_i T_i)^(2/3) (r_i + r_s)/(r_i r_s)
   with g_i(check) from the largest ratio recorded over i's contacts and K_i the largest K over the
   types i can touch. No particle can reach its limit while D stays below
     allowed_i = (1 - g_i(check)) / (2 growth_i)
   for every i: the steps in between need no recording and no check. SI units throughout. */
#ifndef CRUSH_CHECK_BOUND_H
#define CRUSH_CHECK_BOUND_H

namespace crush {

// K = sqrt2 c_N (4E'/3)^2 (Pa^2) of a type pair: c_N the normal coefficient of eq. 8
// (HertzMindlinCoefficients::normal), limit_factor = (4E'/3)^2.
double ratio_coefficient(double normal_coefficient, double limit_factor);

// growth_i (1/m): how fast g = ratio^(2/3) can grow per metre of approach of a particle of radius r,
// strength term T = 1/(pi sigma_lim)^3 and largest ratio coefficient K among its possible contacts,
// when the smallest radius present is r_smallest. Infinite for zero strength.
double ratio_growth(double ratio_coefficient, double strength_term, double radius, double smallest_radius);

// The largest displacement D (m) of any body that provably keeps a particle whose largest ratio at
// the check was 'ratio' below its limit: (1 - margin - ratio^(2/3)) / (2 growth), at least 0. The
// margin (1e-6 of the limit) covers rounding in the contact model's ratio.
double allowed_displacement(double ratio, double growth);

}  // namespace crush

#endif
